// The draw list: everything one frame shows, as plain shapes in pixel coordinates (origin at the
// top-left corner, y down, pixel centres at +0.5). Built from a snapshot with no GL (frame_builder.h)
// and drawn by gl_renderer.h, in the window and offscreen alike. Tests inspect it directly.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "render/colour.h"

namespace polyroll::render {

class FontAtlas;

struct Px {
    float x = 0.0f;
    float y = 0.0f;
    bool operator==(const Px&) const = default;
};

// What an item depicts, so tests (and later picking in the window) can find it.
enum class Tag : std::uint8_t {
    none,
    ramp_body,
    ramp_surface,
    ramp_tick,
    shell_inside,
    shell_wall,
    shell_outline,
    lid_dot,
    grain,
    fill_region,  // a fill held as one body (a full shell, the reduced models), drawn as one region
    panel,
    plot,
    inset_frame,
    inset_marker,
};

// A filled triangle. Not antialiased: its visible edges are stroked with shapes drawn over it.
struct Triangle {
    Px a, b, c;
    Rgba colour;
    Tag tag = Tag::none;
    bool operator==(const Triangle&) const = default;
};

// Shapes drawn by their distance function in the fragment shader, so their edges are antialiased.
enum class ShapeKind : std::uint8_t {
    capsule,  // a thick segment with round ends; a disc when a == b. radius: half the thickness.
    box,      // a rounded rectangle: a is the centre, b the half size; radius: the corner radius.
};

struct Shape {
    ShapeKind kind = ShapeKind::capsule;
    Px a, b;
    float radius = 0.0f;
    float outline_px = 0.0f;  // a band of `outline` colour inside the edge; 0 for none
    Rgba fill;
    Rgba outline;
    Tag tag = Tag::none;
    bool operator==(const Shape&) const = default;
};

// One glyph: a pixel rectangle textured from the font atlas's coverage.
struct GlyphQuad {
    Px p0, p1;             // top-left and bottom-right, whole pixels
    float u0, v0, u1, v1;  // atlas texture coordinates
    Rgba colour;
    bool operator==(const GlyphQuad&) const = default;
};

struct ClipRect {
    int x = 0, y = 0, width = 0, height = 0;  // pixels, top-left origin
    bool operator==(const ClipRect&) const = default;
    bool empty() const { return width <= 0 || height <= 0; }
};

// A layer draws its triangles, then its shapes in order, then its glyphs; layers draw in order.
struct Layer {
    std::optional<ClipRect> clip;
    std::vector<Triangle> triangles;
    std::vector<Shape> shapes;
    std::vector<GlyphQuad> glyphs;
};

struct DrawList {
    int width_px = 0;
    int height_px = 0;
    Rgba background;
    // Draws nothing outside these pixels, not even the clear: the window's scene area, whose
    // surroundings (the panels) are kept from frame to frame. None: the whole frame.
    std::optional<ClipRect> bounds;
    const FontAtlas* atlas = nullptr;  // the texture the glyphs refer to
    std::vector<Layer> layers;

    Layer& new_layer(std::optional<ClipRect> clip = std::nullopt) {
        layers.emplace_back();
        layers.back().clip = clip;
        return layers.back();
    }
};

// Helpers that keep the builders short.
inline Shape disc(Px c, float radius, Rgba fill, Tag tag = Tag::none, float outline_px = 0.0f, Rgba outline = {}) {
    return {ShapeKind::capsule, c, c, radius, outline_px, fill, outline, tag};
}
inline Shape segment(Px a, Px b, float width_px, Rgba colour, Tag tag = Tag::none) {
    return {ShapeKind::capsule, a, b, width_px / 2.0f, 0.0f, colour, colour, tag};
}
inline Shape rounded_box(Px top_left, Px size, float corner_px, Rgba fill, float outline_px, Rgba outline,
                         Tag tag = Tag::none) {
    return {ShapeKind::box,
            {top_left.x + size.x / 2.0f, top_left.y + size.y / 2.0f},
            {size.x / 2.0f, size.y / 2.0f},
            corner_px,
            outline_px,
            fill,
            outline,
            tag};
}

}  // namespace polyroll::render
