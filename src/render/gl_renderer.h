// Draws a draw list with plain OpenGL 3.3 core calls into the current context's framebuffer: the
// same code for the window and the offscreen (OSMesa) context. Triangles as they are; discs as
// point sprites, capsules and rounded boxes as instanced quads, whose fragment shaders antialias the
// edge by distance (far cheaper than multisampling under llvmpipe); glyphs as instanced textured quads.
// Links no GL itself: the executable brings exactly one GL provider (docs/design.md, "Rendering").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/changed_regions.h"
#include "render/disc_splat.h"
#include "render/draw_list.h"

namespace polyroll::render {

class GlRenderer {
public:
    GlRenderer();  // needs a current GL 3.3 core context; throws std::runtime_error on shader errors
    ~GlRenderer();
    GlRenderer(const GlRenderer&) = delete;
    GlRenderer& operator=(const GlRenderer&) = delete;

    // Clears to the list's background and draws it. The viewport is the list's size.
    void draw(const DrawList& list);
    // The same, only inside `regions` (cut to the list's bounds): the framebuffer holds the last
    // frame elsewhere, and these are where this list differs from it (changed_regions.h). Each region
    // is cleared and gets, in the list's order, every primitive that reaches it. `pixels`:
    // pixels_of(list), measured once for the regions and for this.
    void draw(const DrawList& list, const std::vector<ClipRect>& regions, const std::vector<LayerPixels>& pixels);

    // Whether discs of at most kSplatMaxRadiusPx are composited on the CPU (disc_splat.h; the default)
    // or drawn as point sprites like larger ones: the tests compare the two pictures.
    void composite_small_discs(bool on) { composite_small_discs_ = on; }

private:
    void draw_in(const DrawList& list, const std::vector<ClipRect>* regions, const std::vector<LayerPixels>* pixels);
    // Clears `region` and draws the layers there; `whole_frame`: no scissor for the clear or for
    // layers without a clip (the list has no bounds and the region is the frame). `pixels`:
    // pixels_of(list), to send a region smaller than the frame only what reaches it.
    void draw_region(const DrawList& list, const ClipRect& region, bool whole_frame,
                     const std::vector<LayerPixels>& pixels);
    void upload_atlas(const FontAtlas& atlas);
    // Whether a shape is drawn as a point sprite: a disc no wider than GL's largest point, centred in the frame.
    bool as_point(const Shape& s, float width_px, float height_px) const;
    // Discs as point sprites, in order: long runs of one fill and outline with the colours as uniforms,
    // the rest with a colour per point.
    void draw_discs(const std::vector<const Shape*>& shapes, size_t begin, size_t end, float width_px, float height_px);
    void draw_discs_one_colour(const std::vector<const Shape*>& shapes, size_t begin, size_t end, float width_px,
                               float height_px);
    void draw_discs_coloured(const std::vector<const Shape*>& shapes, size_t begin, size_t end, float width_px,
                             float height_px);
    // Small discs (disc_splat.h) composited on the CPU inside `clip`, then drawn as one textured quad.
    void draw_discs_splatted(const std::vector<const Shape*>& shapes, size_t begin, size_t end, const ClipRect& clip,
                             float width_px, float height_px);
    void draw_shapes(const std::vector<const Shape*>& shapes, size_t begin, size_t end, float width_px,
                     float height_px);

    unsigned tri_program_ = 0, shape_program_ = 0, glyph_program_ = 0, disc_program_ = 0, one_colour_program_ = 0;
    unsigned tri_vao_ = 0, shape_vao_ = 0, glyph_vao_ = 0, disc_vao_ = 0, one_colour_vao_ = 0;
    unsigned tri_vbo_ = 0, quad_vbo_ = 0, shape_vbo_ = 0, glyph_vbo_ = 0, disc_vbo_ = 0, one_colour_vbo_ = 0;
    unsigned atlas_texture_ = 0;
    std::uint64_t uploaded_atlas_ = 0;  // FontAtlas::id() of the texture
    int tri_viewport_ = -1, shape_viewport_ = -1, glyph_viewport_ = -1, glyph_sampler_ = -1, disc_viewport_ = -1;
    int one_colour_viewport_ = -1, one_colour_fill_ = -1, one_colour_outline_ = -1;  // discs of one fill and outline
    float max_point_px_ = 1.0f;  // GL's largest point sprite
    unsigned splat_program_ = 0, splat_vao_ = 0;
    std::array<unsigned, 4> splat_textures_{};  // used in turn (gl_renderer.cpp says why)
    std::array<std::array<int, 2>, 4> splat_texture_px_{};  // each one's allocated width and height
    size_t next_splat_texture_ = 0;
    int splat_viewport_ = -1, splat_rect_ = -1, splat_origin_ = -1, splat_sampler_ = -1;
    bool composite_small_discs_ = true;
    DiscSplat splat_;                   // the last run of small discs composited, kept for its buffer
    SplatScratch splat_scratch_;        // its working memory
};

}  // namespace polyroll::render
