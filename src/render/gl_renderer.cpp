// The GL 3.3 core drawing of a draw list: see gl_renderer.h.
#define GL_GLEXT_PROTOTYPES 1
#include "render/gl_renderer.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "render/changed_regions.h"
#include "render/disc_splat.h"
#include "render/font.h"
#include "render/gl_program.h"

namespace polyroll::render {

namespace {

// Pixel coordinates (top-left origin) to clip space, shared by the three programs.
constexpr const char* kToClip = R"(
vec4 to_clip(vec2 p, vec2 viewport) {
    return vec4(p.x / viewport.x * 2.0 - 1.0, 1.0 - p.y / viewport.y * 2.0, 0.0, 1.0);
}
)";

constexpr const char* kTriVertex = R"(
layout(location = 0) in vec2 pos;
layout(location = 1) in vec4 colour;
uniform vec2 viewport;
out vec4 v_colour;
void main() {
    v_colour = colour;
    gl_Position = to_clip(pos, viewport);
}
)";
constexpr const char* kTriFragment = R"(
in vec4 v_colour;
out vec4 frag;
void main() { frag = v_colour; }
)";

// One quad per shape, just large enough to hold it and its one-pixel antialiasing fringe.
constexpr const char* kShapeVertex = R"(
layout(location = 0) in vec2 corner;
layout(location = 1) in vec4 ab;
layout(location = 2) in vec4 params;  // kind, radius, outline width
layout(location = 3) in vec4 fill;
layout(location = 4) in vec4 outline;
uniform vec2 viewport;
out vec2 p;
flat out vec4 v_ab;
flat out vec4 v_params;
flat out vec4 v_fill;
flat out vec4 v_outline;
void main() {
    if (params.x < 0.5) {
        // Aligned with the segment, so a long diagonal line shades only the pixels near it.
        vec2 d = ab.zw - ab.xy;
        float len = length(d);
        vec2 along = len > 1e-4 ? d / len : vec2(1.0, 0.0);
        vec2 across = vec2(-along.y, along.x);
        float e = params.y + 1.0;
        p = ab.xy + along * (mix(-e, len + e, corner.x)) + across * mix(-e, e, corner.y);
    } else {
        p = mix(ab.xy - ab.zw - vec2(1.0), ab.xy + ab.zw + vec2(1.0), corner);
    }
    v_ab = ab;
    v_params = params;
    v_fill = fill;
    v_outline = outline;
    gl_Position = to_clip(p, viewport);
}
)";
constexpr const char* kShapeFragment = R"(
in vec2 p;
flat in vec4 v_ab;
flat in vec4 v_params;
flat in vec4 v_fill;
flat in vec4 v_outline;
out vec4 frag;
void main() {
    float d;
    float r = v_params.y;
    if (v_params.x < 0.5) {
        vec2 pa = p - v_ab.xy, ba = v_ab.zw - v_ab.xy;
        float len2 = dot(ba, ba);
        float h = len2 > 0.0 ? clamp(dot(pa, ba) / len2, 0.0, 1.0) : 0.0;
        d = length(pa - ba * h) - r;
    } else {
        vec2 q = abs(p - v_ab.xy) - (v_ab.zw - vec2(r));
        d = length(max(q, vec2(0.0))) + min(max(q.x, q.y), 0.0) - r;
    }
    // Coverage falls from 1 to 0 across the pixel straddling the edge.
    float cover = clamp(0.5 - d, 0.0, 1.0);
    vec4 c = v_fill;
    if (v_params.z > 0.0) c = mix(v_outline, v_fill, clamp(-(d + v_params.z) + 0.5, 0.0, 1.0));
    frag = vec4(c.rgb, c.a * cover);
}
)";

// A disc as one point sprite, as wide as the quad a shape would get: one primitive where the quad
// is two. A software GL (llvmpipe: the window under Xvfb and every headless frame) pays per primitive
// more than per pixel for small discs: 3,000 grains of a couple of pixels drew about twice as fast
// as points. The distance is measured from the pixel's own centre (gl_FragCoord), as the shapes'
// quads interpolate it, with the same edge and outline as a capsule of zero length.
constexpr const char* kDiscVertex = R"(
layout(location = 0) in vec4 disc;  // centre x, y, radius, outline width
layout(location = 1) in vec4 fill;
layout(location = 2) in vec4 outline;
uniform vec2 viewport;
flat out vec4 v_disc;
flat out vec4 v_fill;
flat out vec4 v_outline;
void main() {
    v_disc = disc;
    v_fill = fill;
    v_outline = outline;
    gl_PointSize = 2.0 * disc.z + 2.0;
    gl_Position = to_clip(disc.xy, viewport);
}
)";
// The fragment's colour, shared by both disc programs' fragment shaders.
constexpr const char* kDiscShading = R"(
vec4 disc_colour(vec4 disc, vec4 fill, vec4 outline, vec2 viewport) {
    vec2 p = vec2(gl_FragCoord.x, viewport.y - gl_FragCoord.y);
    float d = length(p - disc.xy) - disc.z;
    float cover = clamp(0.5 - d, 0.0, 1.0);
    vec4 c = fill;
    if (disc.w > 0.0) c = mix(outline, fill, clamp(-(d + disc.w) + 0.5, 0.0, 1.0));
    return vec4(c.rgb, c.a * cover);
}
)";
constexpr const char* kDiscFragment = R"(
flat in vec4 v_disc;
flat in vec4 v_fill;
flat in vec4 v_outline;
uniform vec2 viewport;
out vec4 frag;
void main() { frag = disc_colour(v_disc, v_fill, v_outline, viewport); }
)";
// Discs of one fill and one outline (every grain of a pile coloured by its material): the colours are
// uniforms and each point carries only its centre, radius and outline width. A software GL sets up
// every input of every point: with one input instead of three, hexagon-large-bb's 2 x 1,709 discs
// took about 0.9 ms less of the 2.8 they cost under llvmpipe (docs/sandbox.md).
constexpr const char* kDiscVertexOneColour = R"(
layout(location = 0) in vec4 disc;  // centre x, y, radius, outline width
uniform vec2 viewport;
flat out vec4 v_disc;
void main() {
    v_disc = disc;
    gl_PointSize = 2.0 * disc.z + 2.0;
    gl_Position = to_clip(disc.xy, viewport);
}
)";
constexpr const char* kDiscFragmentOneColour = R"(
flat in vec4 v_disc;
uniform vec2 viewport;
uniform vec4 fill;
uniform vec4 outline;
out vec4 frag;
void main() { frag = disc_colour(v_disc, fill, outline, viewport); }
)";

// The discs composited on the CPU (disc_splat.h): one quad over their pixels, each pixel its texel,
// fetched by whole pixel so nothing is filtered. The texel is premultiplied (blended ONE,
// ONE_MINUS_SRC_ALPHA).
constexpr const char* kSplatVertex = R"(
layout(location = 0) in vec2 corner;
uniform vec2 viewport;
uniform vec4 rect;  // left, top, right, bottom, pixels
void main() { gl_Position = to_clip(mix(rect.xy, rect.zw, corner), viewport); }
)";
constexpr const char* kSplatFragment = R"(
uniform highp sampler2D splat;
uniform ivec2 origin;  // the texture's top-left pixel
uniform vec2 viewport;
out vec4 frag;
void main() {
    ivec2 texel = ivec2(int(floor(gl_FragCoord.x)), int(floor(viewport.y - gl_FragCoord.y))) - origin;
    frag = texelFetch(splat, texel, 0);
}
)";

constexpr const char* kGlyphVertex = R"(
layout(location = 0) in vec2 corner;
layout(location = 1) in vec4 rect;
layout(location = 2) in vec4 uv;
layout(location = 3) in vec4 colour;
uniform vec2 viewport;
out vec2 v_uv;
flat out vec4 v_colour;
void main() {
    v_uv = mix(uv.xy, uv.zw, corner);
    v_colour = colour;
    gl_Position = to_clip(mix(rect.xy, rect.zw, corner), viewport);
}
)";
constexpr const char* kGlyphFragment = R"(
in vec2 v_uv;
flat in vec4 v_colour;
uniform sampler2D atlas;
out vec4 frag;
void main() { frag = vec4(v_colour.rgb, v_colour.a * texture(atlas, v_uv).r); }
)";

// The per-instance layout of a shape: a.xy b.xy | kind radius outline 0 | fill | outline.
struct ShapeInstance {
    float ab[4];
    float params[4];
    float fill[4];
    float outline[4];
};
struct DiscVertex {
    float disc[4];
    float fill[4];
    float outline[4];
};
struct GlyphInstance {
    float rect[4];
    float uv[4];
    float colour[4];
};
struct TriVertex {
    float x, y;
    float colour[4];
};

void float_attrib(GLuint index, int size, GLsizei stride, size_t offset, bool instanced) {
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
    glVertexAttribDivisor(index, instanced ? 1 : 0);
}

void put(float* dst, const Rgba& c) {
    dst[0] = c.r;
    dst[1] = c.g;
    dst[2] = c.b;
    dst[3] = c.a;
}

}  // namespace

GlRenderer::GlRenderer() {
    tri_program_ = link_program(kTriVertex, kTriFragment, kToClip);
    shape_program_ = link_program(kShapeVertex, kShapeFragment, kToClip);
    glyph_program_ = link_program(kGlyphVertex, kGlyphFragment, kToClip);
    tri_viewport_ = glGetUniformLocation(tri_program_, "viewport");
    shape_viewport_ = glGetUniformLocation(shape_program_, "viewport");
    glyph_viewport_ = glGetUniformLocation(glyph_program_, "viewport");
    glyph_sampler_ = glGetUniformLocation(glyph_program_, "atlas");
    const std::string disc_fragment = std::string(kDiscShading) + kDiscFragment;
    disc_program_ = link_program(kDiscVertex, disc_fragment.c_str(), kToClip);
    disc_viewport_ = glGetUniformLocation(disc_program_, "viewport");
    const std::string one_colour_fragment = std::string(kDiscShading) + kDiscFragmentOneColour;
    one_colour_program_ = link_program(kDiscVertexOneColour, one_colour_fragment.c_str(), kToClip);
    one_colour_viewport_ = glGetUniformLocation(one_colour_program_, "viewport");
    one_colour_fill_ = glGetUniformLocation(one_colour_program_, "fill");
    one_colour_outline_ = glGetUniformLocation(one_colour_program_, "outline");
    splat_program_ = link_program(kSplatVertex, kSplatFragment, kToClip);
    splat_viewport_ = glGetUniformLocation(splat_program_, "viewport");
    splat_rect_ = glGetUniformLocation(splat_program_, "rect");
    splat_origin_ = glGetUniformLocation(splat_program_, "origin");
    splat_sampler_ = glGetUniformLocation(splat_program_, "splat");
    float point_sizes[2] = {1.0f, 1.0f};
    glGetFloatv(GL_ALIASED_POINT_SIZE_RANGE, point_sizes);
    max_point_px_ = point_sizes[1];

    static const float corners[8] = {0, 0, 1, 0, 0, 1, 1, 1};  // a triangle strip
    glGenBuffers(1, &quad_vbo_);
    glBindBuffer(GL_ARRAY_BUFFER, quad_vbo_);
    glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);

    glGenVertexArrays(1, &tri_vao_);
    glGenBuffers(1, &tri_vbo_);
    glBindVertexArray(tri_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, tri_vbo_);
    float_attrib(0, 2, sizeof(TriVertex), offsetof(TriVertex, x), false);
    float_attrib(1, 4, sizeof(TriVertex), offsetof(TriVertex, colour), false);

    glGenVertexArrays(1, &shape_vao_);
    glGenBuffers(1, &shape_vbo_);
    glBindVertexArray(shape_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, quad_vbo_);
    float_attrib(0, 2, 2 * sizeof(float), 0, false);
    glBindBuffer(GL_ARRAY_BUFFER, shape_vbo_);
    float_attrib(1, 4, sizeof(ShapeInstance), offsetof(ShapeInstance, ab), true);
    float_attrib(2, 4, sizeof(ShapeInstance), offsetof(ShapeInstance, params), true);
    float_attrib(3, 4, sizeof(ShapeInstance), offsetof(ShapeInstance, fill), true);
    float_attrib(4, 4, sizeof(ShapeInstance), offsetof(ShapeInstance, outline), true);

    glGenVertexArrays(1, &glyph_vao_);
    glGenBuffers(1, &glyph_vbo_);
    glBindVertexArray(glyph_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, quad_vbo_);
    float_attrib(0, 2, 2 * sizeof(float), 0, false);
    glBindBuffer(GL_ARRAY_BUFFER, glyph_vbo_);
    float_attrib(1, 4, sizeof(GlyphInstance), offsetof(GlyphInstance, rect), true);
    float_attrib(2, 4, sizeof(GlyphInstance), offsetof(GlyphInstance, uv), true);
    float_attrib(3, 4, sizeof(GlyphInstance), offsetof(GlyphInstance, colour), true);

    glGenVertexArrays(1, &disc_vao_);
    glGenBuffers(1, &disc_vbo_);
    glBindVertexArray(disc_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, disc_vbo_);
    float_attrib(0, 4, sizeof(DiscVertex), offsetof(DiscVertex, disc), false);
    float_attrib(1, 4, sizeof(DiscVertex), offsetof(DiscVertex, fill), false);
    float_attrib(2, 4, sizeof(DiscVertex), offsetof(DiscVertex, outline), false);

    glGenVertexArrays(1, &one_colour_vao_);
    glGenBuffers(1, &one_colour_vbo_);
    glBindVertexArray(one_colour_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, one_colour_vbo_);
    float_attrib(0, 4, 4 * sizeof(float), 0, false);

    glGenVertexArrays(1, &splat_vao_);
    glBindVertexArray(splat_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, quad_vbo_);
    float_attrib(0, 2, 2 * sizeof(float), 0, false);

    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glGenTextures(1, &atlas_texture_);
    glGenTextures(static_cast<GLsizei>(splat_textures_.size()), splat_textures_.data());
    for (const GLuint t : splat_textures_) {
        glBindTexture(GL_TEXTURE_2D, t);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
}

GlRenderer::~GlRenderer() {
    glDeleteTextures(1, &atlas_texture_);
    glDeleteTextures(static_cast<GLsizei>(splat_textures_.size()), splat_textures_.data());
    const GLuint buffers[6] = {tri_vbo_, quad_vbo_, shape_vbo_, glyph_vbo_, disc_vbo_, one_colour_vbo_};
    glDeleteBuffers(6, buffers);
    const GLuint arrays[6] = {tri_vao_, shape_vao_, glyph_vao_, disc_vao_, one_colour_vao_, splat_vao_};
    glDeleteVertexArrays(6, arrays);
    glDeleteProgram(splat_program_);
    glDeleteProgram(disc_program_);
    glDeleteProgram(one_colour_program_);
    glDeleteProgram(tri_program_);
    glDeleteProgram(shape_program_);
    glDeleteProgram(glyph_program_);
}

void GlRenderer::upload_atlas(const FontAtlas& atlas) {
    glBindTexture(GL_TEXTURE_2D, atlas_texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, atlas.width(), atlas.height(), 0, GL_RED, GL_UNSIGNED_BYTE,
                 atlas.coverage().data());
    // Glyph quads sit on whole pixels at the atlas's own scale: nearest sampling copies texels exactly.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    uploaded_atlas_ = atlas.id();
}

bool GlRenderer::as_point(const Shape& s, float width_px, float height_px) const {
    // A point whose centre lies outside the viewport is clipped whole, so a disc cut by the frame's
    // edge stays a quad.
    return s.kind == ShapeKind::capsule && s.a.x == s.b.x && s.a.y == s.b.y && 2.0f * s.radius + 2.0f <= max_point_px_ &&
           s.a.x >= 0.0f && s.a.x <= width_px && s.a.y >= 0.0f && s.a.y <= height_px;
}

// Shorter runs of one colour go with their neighbours through the per-point colours: a program
// switch and a draw each would cost more than the inputs saved (a pile coloured by speed has a colour
// per grain).
constexpr size_t kOneColourRunMin = 32;

void GlRenderer::draw_discs(const std::vector<const Shape*>& shapes, size_t begin, size_t end, float width_px,
                            float height_px) {
    size_t pending = begin;  // the start of discs not drawn yet, bound for the per-point colours
    for (size_t i = begin; i < end;) {
        size_t j = i + 1;
        while (j < end && shapes[j]->fill == shapes[i]->fill && shapes[j]->outline == shapes[i]->outline) ++j;
        if (j - i >= kOneColourRunMin) {
            if (pending < i) draw_discs_coloured(shapes, pending, i, width_px, height_px);
            draw_discs_one_colour(shapes, i, j, width_px, height_px);
            pending = j;
        }
        i = j;
    }
    if (pending < end) draw_discs_coloured(shapes, pending, end, width_px, height_px);
}

void GlRenderer::draw_discs_one_colour(const std::vector<const Shape*>& shapes, size_t begin, size_t end,
                                       float width_px, float height_px) {
    const Shape& first = *shapes[begin];
    std::vector<float> discs;
    discs.reserve(4 * (end - begin));
    for (size_t i = begin; i < end; ++i) {
        const Shape& s = *shapes[i];
        discs.insert(discs.end(), {s.a.x, s.a.y, s.radius, s.outline_px});
    }
    glUseProgram(one_colour_program_);
    glUniform2f(one_colour_viewport_, width_px, height_px);
    glUniform4f(one_colour_fill_, first.fill.r, first.fill.g, first.fill.b, first.fill.a);
    glUniform4f(one_colour_outline_, first.outline.r, first.outline.g, first.outline.b, first.outline.a);
    glBindVertexArray(one_colour_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, one_colour_vbo_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(discs.size() * sizeof(float)), discs.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(end - begin));
}

void GlRenderer::draw_discs_coloured(const std::vector<const Shape*>& shapes, size_t begin, size_t end, float width_px,
                                     float height_px) {
    std::vector<DiscVertex> discs;
    discs.reserve(end - begin);
    for (size_t i = begin; i < end; ++i) {
        const Shape& s = *shapes[i];
        DiscVertex v{{s.a.x, s.a.y, s.radius, s.outline_px}, {}, {}};
        put(v.fill, s.fill);
        put(v.outline, s.outline);
        discs.push_back(v);
    }
    glUseProgram(disc_program_);
    glUniform2f(disc_viewport_, width_px, height_px);
    glBindVertexArray(disc_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, disc_vbo_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(discs.size() * sizeof(DiscVertex)), discs.data(),
                 GL_STREAM_DRAW);
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(discs.size()));
}

void GlRenderer::draw_discs_splatted(const std::vector<const Shape*>& shapes, size_t begin, size_t end,
                                     const ClipRect& clip, float width_px, float height_px) {
    splat_discs(shapes, begin, end, clip, splat_, splat_scratch_);
    if (splat_.box.empty()) return;
    const ClipRect& b = splat_.box;
    glActiveTexture(GL_TEXTURE0);
    // A texture of its own for each of a frame's first few runs: writing one a draw still waits for
    // makes a software GL finish that draw first.
    const size_t k = next_splat_texture_;
    next_splat_texture_ = (next_splat_texture_ + 1) % splat_textures_.size();
    glBindTexture(GL_TEXTURE_2D, splat_textures_[k]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // The image goes into the texture's top-left corner (the shader fetches by offset from `origin`);
    // the texture grows only when an image does not fit, so most frames reallocate nothing.
    std::array<int, 2>& size = splat_texture_px_[k];
    if (b.width > size[0] || b.height > size[1]) {
        size = {std::max(b.width, size[0]), std::max(b.height, size[1])};
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size[0], size[1], 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    }
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, b.width, b.height, GL_RGBA, GL_UNSIGNED_BYTE, splat_.rgba.data());
    glUseProgram(splat_program_);
    glUniform2f(splat_viewport_, width_px, height_px);
    glUniform4f(splat_rect_, static_cast<float>(b.x), static_cast<float>(b.y), static_cast<float>(b.x + b.width),
                static_cast<float>(b.y + b.height));
    glUniform2i(splat_origin_, b.x, b.y);
    glUniform1i(splat_sampler_, 0);
    glBindVertexArray(splat_vao_);
    glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
}

void GlRenderer::draw_shapes(const std::vector<const Shape*>& shapes, size_t begin, size_t end, float width_px,
                             float height_px) {
    std::vector<ShapeInstance> instances;
    instances.reserve(end - begin);
    for (size_t i = begin; i < end; ++i) {
        const Shape& s = *shapes[i];
        ShapeInstance in{{s.a.x, s.a.y, s.b.x, s.b.y},
                         {s.kind == ShapeKind::box ? 1.0f : 0.0f, s.radius, s.outline_px, 0.0f},
                         {},
                         {}};
        put(in.fill, s.fill);
        put(in.outline, s.outline);
        instances.push_back(in);
    }
    glUseProgram(shape_program_);
    glUniform2f(shape_viewport_, width_px, height_px);
    glBindVertexArray(shape_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, shape_vbo_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(instances.size() * sizeof(ShapeInstance)), instances.data(),
                 GL_STREAM_DRAW);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(instances.size()));
}

void GlRenderer::draw(const DrawList& list) { draw_in(list, nullptr, nullptr); }

void GlRenderer::draw(const DrawList& list, const std::vector<ClipRect>& regions,
                      const std::vector<LayerPixels>& pixels) {
    draw_in(list, &regions, &pixels);
}

void GlRenderer::draw_in(const DrawList& list, const std::vector<ClipRect>* regions,
                         const std::vector<LayerPixels>* pixels) {
    const int w = list.width_px, h = list.height_px;
    glViewport(0, 0, w, h);
    glDisable(GL_DEPTH_TEST);
    glClearColor(list.background.r, list.background.g, list.background.b, 1.0f);
    glEnable(GL_BLEND);
    // Alpha kept at 1 over the opaque background, so the read-back RGB is the picture.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
#ifndef POLYROLL_GLSL_ES
    glEnable(GL_PROGRAM_POINT_SIZE);  // the point sprites' size from the shader (always so in GLES and WebGL)
#endif
    if (list.atlas && list.atlas->id() != uploaded_atlas_) upload_atlas(*list.atlas);
    const ClipRect frame = list.bounds ? *list.bounds : ClipRect{0, 0, w, h};
    if (!regions) {
        // The whole list: the clear scissored to its bounds (where it has them), each layer to its clip.
        // Culled to the bounds where there are some.
        draw_region(list, frame, !list.bounds, list.bounds ? pixels_of(list) : std::vector<LayerPixels>{});
    } else {
        for (const ClipRect& r : *regions) {
            const ClipRect region = intersection(r, frame);
            if (!region.empty()) draw_region(list, region, false, *pixels);
        }
    }
    glDisable(GL_SCISSOR_TEST);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glUseProgram(0);
}

void GlRenderer::draw_region(const DrawList& list, const ClipRect& region, bool whole_frame,
                             const std::vector<LayerPixels>& pixels) {
    const int h = list.height_px;
    // GL counts rows from the bottom.
    const auto scissor = [h](const ClipRect& c) { glScissor(c.x, h - c.y - c.height, c.width, c.height); };
    if (whole_frame) {
        glDisable(GL_SCISSOR_TEST);
    } else {
        glEnable(GL_SCISSOR_TEST);
        scissor(region);
    }
    glClear(GL_COLOR_BUFFER_BIT);
    // Inside a region smaller than the frame only the primitives that reach it are sent (culled by
    // the same pixels changed_regions counts); the scissor keeps each to the region's pixels.
    const ClipRect frame{0, 0, list.width_px, h};
    const bool cull = !(region == frame);
    std::vector<TriVertex> tris;
    std::vector<GlyphInstance> glyphs;
    std::vector<const Shape*> shapes;
    std::vector<size_t> batches;  // for each of `shapes`, its run of small discs (see below)
    const float fw = static_cast<float>(list.width_px), fh = static_cast<float>(h);
    for (size_t li = 0; li < list.layers.size(); ++li) {
        const Layer& layer = list.layers[li];
        const ClipRect clip = layer.clip ? intersection(*layer.clip, region) : region;
        if (clip.empty()) continue;
        if (whole_frame && !layer.clip) {
            glDisable(GL_SCISSOR_TEST);
        } else {
            glEnable(GL_SCISSOR_TEST);
            scissor(clip);
        }
        // Whether the layer's item `i` of a kind reaches the clip, by its pixels as pixels_of measured
        // them (only read when culling: a whole frame without bounds has none).
        const auto reaches = [&](const std::vector<ClipRect> LayerPixels::*kind, size_t i) {
            return !cull || overlap((pixels[li].*kind)[i], clip);
        };
        tris.clear();
        // Decided by all of the layer's triangles, culled or not, so that a region blends as the whole
        // frame does.
        const bool opaque = std::all_of(layer.triangles.begin(), layer.triangles.end(),
                                        [](const Triangle& t) { return t.colour.a >= 1.0f; });
        for (size_t i = 0; i < layer.triangles.size(); ++i) {
            const Triangle& t = layer.triangles[i];
            if (!reaches(&LayerPixels::triangles, i)) continue;
            for (const Px& p : {t.a, t.b, t.c}) {
                TriVertex v{p.x, p.y, {}};
                put(v.colour, t.colour);
                tris.push_back(v);
            }
        }
        if (!tris.empty()) {
            // Opaque triangles replace what is under them, blended or not; unblended, a software GL
            // fills them about three times faster.
            if (opaque) glDisable(GL_BLEND);
            glUseProgram(tri_program_);
            glUniform2f(tri_viewport_, fw, fh);
            glBindVertexArray(tri_vao_);
            glBindBuffer(GL_ARRAY_BUFFER, tri_vbo_);
            glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(tris.size() * sizeof(TriVertex)), tris.data(),
                         GL_STREAM_DRAW);
            glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(tris.size()));
            glEnable(GL_BLEND);
        }
        shapes.clear();
        batches.clear();
        // A run of small discs is composited as one image (disc_splat.h), rounded to 8 bits once. The
        // runs are cut where the whole layer has another shape between two discs, culled from this
        // region or not, so that every region rounds a pixel as the whole frame does.
        const auto composited = [this](const Shape& s) { return composite_small_discs_ && splat_eligible(s); };
        size_t batch = 0;
        for (size_t i = 0; i < layer.shapes.size(); ++i) {
            if (!composited(layer.shapes[i])) ++batch;
            if (!reaches(&LayerPixels::shapes, i)) continue;
            shapes.push_back(&layer.shapes[i]);
            batches.push_back(batch);
        }
        // The shapes in order: each run of small discs composited, each run of other discs that fit a
        // point sprite as points, the rest as quads.
        enum class Way { splat, points, quads };
        const auto way = [&](const Shape& s) {
            return composited(s) ? Way::splat : as_point(s, fw, fh) ? Way::points : Way::quads;
        };
        for (size_t i = 0; i < shapes.size();) {
            const Way w = way(*shapes[i]);
            size_t end = i + 1;
            while (end < shapes.size() && way(*shapes[end]) == w && (w != Way::splat || batches[end] == batches[i])) ++end;
            if (w == Way::splat) draw_discs_splatted(shapes, i, end, clip, fw, fh);
            else if (w == Way::points) draw_discs(shapes, i, end, fw, fh);
            else draw_shapes(shapes, i, end, fw, fh);
            i = end;
        }
        glyphs.clear();
        if (list.atlas)
            for (size_t i = 0; i < layer.glyphs.size(); ++i) {
                const GlyphQuad& g = layer.glyphs[i];
                if (!reaches(&LayerPixels::glyphs, i)) continue;
                GlyphInstance in{{g.p0.x, g.p0.y, g.p1.x, g.p1.y}, {g.u0, g.v0, g.u1, g.v1}, {}};
                put(in.colour, g.colour);
                glyphs.push_back(in);
            }
        if (!glyphs.empty()) {
            glUseProgram(glyph_program_);
            glUniform2f(glyph_viewport_, fw, fh);
            glUniform1i(glyph_sampler_, 0);
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D, atlas_texture_);
            glBindVertexArray(glyph_vao_);
            glBindBuffer(GL_ARRAY_BUFFER, glyph_vbo_);
            glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(glyphs.size() * sizeof(GlyphInstance)),
                         glyphs.data(), GL_STREAM_DRAW);
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(glyphs.size()));
        }
    }
}

}  // namespace polyroll::render
