// The close-up inset: see close_up.h.
#include "render/close_up.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

namespace polyroll::render {

namespace {

// Share of the inset's height the polygon's outer radius spans.
constexpr double kInsetRadiusShare = 0.30;

// A rectangle's outline as four segments: an unfilled box shape would shade its whole inside.
void outline_rect(Layer& out, PxRect r, float width, Rgba colour, Tag tag) {
    const Px tl{r.x, r.y}, tr{r.x + r.width, r.y}, br{r.x + r.width, r.y + r.height}, bl{r.x, r.y + r.height};
    out.shapes.push_back(segment(tl, tr, width, colour, tag));
    out.shapes.push_back(segment(tr, br, width, colour, tag));
    out.shapes.push_back(segment(br, bl, width, colour, tag));
    out.shapes.push_back(segment(bl, tl, width, colour, tag));
}

// The inset's camera and its label ("close-up ×N" names the camera's magnification): the shell
// centred in the inset or, where the label would cover it (a short inset at a large UI scale), centred
// in the part below the label, a little smaller.
struct Framing {
    Camera cam;
    std::string label;
};
Framing close_up_framing(const Snapshot& s, const Camera& main_cam, const CloseUpStyle& style, const FontAtlas& font) {
    const PxRect r = style.rect;
    const double R = outer_radius_m(s);
    const auto framing = [&](PxRect area) {
        const Camera cam = follow_camera(s.shell_centre_m, s.ramp_angle_deg, R, kInsetRadiusShare, area);
        const double magnification = cam.px_per_m / main_cam.px_per_m;
        return Framing{cam, fmt::format("close-up \u00D7{:.0f}{}", magnification, style.label_suffix)};
    };
    Framing whole = framing(r);
    const float gap = 4.0f * style.unit;
    const float label_bottom = r.y + style.label_offset.y + font.line_height(style.label_font) + gap;
    const float label_right = r.x + style.label_offset.x + font.text_width(whole.label, style.label_font) + gap;
    const float shell_px = static_cast<float>(R * whole.cam.px_per_m);
    const bool covered = whole.cam.anchor.y - shell_px < label_bottom && whole.cam.anchor.x - shell_px < label_right;
    const float below_h = r.y + r.height - label_bottom;
    if (!covered || below_h <= 0.0f) return whole;
    return framing({r.x, label_bottom, r.width, below_h});
}

}  // namespace

CloseUpStyle close_up_style(PxRect rect, float unit) {
    CloseUpStyle style;
    style.rect = rect;
    style.unit = unit;
    style.marker = palette::inset_marker;
    style.border = palette::inset_border;
    style.label_font = label_font(unit);
    const float pad = 10.0f * unit;
    style.label_offset = {pad, pad};
    return style;
}

void draw_close_up(const Snapshot& s, const Camera& main_cam, const CloseUpStyle& style, WorldStyle world,
                   const FontAtlas& font, DrawList& dl) {
    const PxRect r = style.rect;
    const float u = style.unit;
    const double R = outer_radius_m(s);
    const FontSpec f = style.label_font;
    const auto [cam, text] = close_up_framing(s, main_cam, style, font);

    // Where the close-up looks, marked in the main view.
    {
        Layer& mark = dl.new_layer();
        const Px c = main_cam.to_px(ramp_to_world(s.shell_centre_m, s.ramp_angle_deg));
        const float half = std::max(8.0f * u, main_cam.to_px_length(R) * 1.6f);
        outline_rect(mark, {c.x - half, c.y - half, 2 * half, 2 * half}, std::max(1.0f, 2.0f * u), style.marker,
                     Tag::inset_marker);
    }
    const ClipRect clip{static_cast<int>(std::lround(r.x)), static_cast<int>(std::lround(r.y)),
                        static_cast<int>(std::lround(r.width)), static_cast<int>(std::lround(r.height))};
    Layer& inner = dl.new_layer(clip);
    // Clipped, so plain triangles: no edge to antialias.
    const Px tl{r.x, r.y}, tr{r.x + r.width, r.y}, br{r.x + r.width, r.y + r.height}, bl{r.x, r.y + r.height};
    inner.triangles.push_back({tl, tr, br, palette::background, Tag::inset_frame});
    inner.triangles.push_back({tl, br, bl, palette::background, Tag::inset_frame});
    world.visible = r;
    draw_world(s, cam, world, font, dl.new_layer(clip));

    Layer& frame = dl.new_layer();
    outline_rect(frame, r, std::max(1.0f, 2.5f * u), style.border, Tag::inset_frame);
    font.layout(text, f, {r.x + style.label_offset.x, r.y + style.label_offset.y + font.ascent(f)}, palette::text_dim,
                frame.glyphs);
}

}  // namespace polyroll::render
