// One frame's draw list: see frame_builder.h.
#include "render/frame_builder.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "render/overlay.h"
#include "render/world_draw.h"

namespace polyroll::render {

namespace {

double outer_radius_m(const Snapshot& s) {
    double r = 0.0;
    for (const geom::Vec2& v : s.outer_local_m) r = std::max(r, geom::length(v));
    return r;
}

// A rectangle's outline as four segments: an unfilled box shape would shade its whole inside.
void outline_rect(Layer& out, PxRect r, float width, Rgba colour, Tag tag) {
    const Px tl{r.x, r.y}, tr{r.x + r.width, r.y}, br{r.x + r.width, r.y + r.height}, bl{r.x, r.y + r.height};
    out.shapes.push_back(segment(tl, tr, width, colour, tag));
    out.shapes.push_back(segment(tr, br, width, colour, tag));
    out.shapes.push_back(segment(br, bl, width, colour, tag));
    out.shapes.push_back(segment(bl, tl, width, colour, tag));
}

// Share of the view's height the shell's outer radius spans when followed.
constexpr double kFollowRadiusShare = 0.24;
constexpr double kInsetRadiusShare = 0.30;

WorldStyle world_style(const FrameOptions& o, const FrameLayout& L, PxRect visible) {
    WorldStyle st;
    st.unit = L.unit;
    st.stroke = L.stroke;
    st.scale_font = L.small;
    st.visible = visible;
    st.grain_colouring = o.grain_colouring;
    st.colour_speed_max_m_s = o.colour_speed_max_m_s;
    return st;
}

void draw_inset(const Snapshot& s, const FrameOptions& o, const FrameLayout& L, const FontAtlas& font,
                const Camera& main_cam, DrawList& dl) {
    const PxRect r = *L.inset;
    const float u = L.unit;
    const double R = outer_radius_m(s);
    const Camera cam = follow_camera(s.shell_centre_m, s.ramp_angle_deg, R, kInsetRadiusShare, r);

    // Where the close-up looks, marked in the main view.
    {
        Layer& mark = dl.new_layer();
        const Px c = main_cam.to_px(ramp_to_world(s.shell_centre_m, s.ramp_angle_deg));
        const float half = std::max(8.0f * u, main_cam.to_px_length(R) * 1.6f);
        outline_rect(mark, {c.x - half, c.y - half, 2 * half, 2 * half}, std::max(1.0f, 2.0f * u),
                     palette::inset_marker, Tag::inset_marker);
    }
    const ClipRect clip{static_cast<int>(std::lround(r.x)), static_cast<int>(std::lround(r.y)),
                        static_cast<int>(std::lround(r.width)), static_cast<int>(std::lround(r.height))};
    Layer& inner = dl.new_layer(clip);
    // Clipped, so plain triangles: no edge to antialias.
    const Px tl{r.x, r.y}, tr{r.x + r.width, r.y}, br{r.x + r.width, r.y + r.height}, bl{r.x, r.y + r.height};
    inner.triangles.push_back({tl, tr, br, palette::background, Tag::inset_frame});
    inner.triangles.push_back({tl, br, bl, palette::background, Tag::inset_frame});
    Layer& world = dl.new_layer(clip);
    draw_world(s, cam, world_style(o, L, r), font, world);

    Layer& frame = dl.new_layer();
    outline_rect(frame, r, std::max(1.0f, 2.5f * u), palette::inset_border, Tag::inset_frame);
    const float pad = 10.0f * u;
    const double mag = cam.px_per_m / main_cam.px_per_m;
    font.layout(fmt::format("close-up \u00D7{:.0f}", mag), L.label, {r.x + pad, r.y + pad + font.ascent(L.label)},
                palette::text_dim, frame.glyphs);
}

}  // namespace

Camera main_camera(const Snapshot& s, const FrameOptions& o, const FrameLayout& L) {
    const double R = outer_radius_m(s);
    if (o.follow) {
        // Follow the shell in the middle of the frame below the overlay, at a fixed zoom.
        PxRect area = L.world;
        return follow_camera(s.shell_centre_m, s.ramp_angle_deg, R,
                             kFollowRadiusShare * static_cast<double>(o.height_px) / area.height, area);
    }
    return whole_ramp_camera(s.ramp_length_m, s.ramp_angle_deg, 2.2 * R, L.world);
}

DrawList build_frame(const Snapshot& s, const FrameOptions& o, const FontAtlas& font) {
    const FrameLayout L = frame_layout(o);
    DrawList dl;
    dl.width_px = o.width_px;
    dl.height_px = o.height_px;
    dl.background = palette::background;
    dl.atlas = &font;
    const Camera cam = main_camera(s, o, L);
    const PxRect full{0.0f, 0.0f, static_cast<float>(o.width_px), static_cast<float>(o.height_px)};
    draw_world(s, cam, world_style(o, L, full), font, dl.new_layer());
    if (L.inset) draw_inset(s, o, L, font, cam, dl);
    Layer& overlay = dl.new_layer();
    draw_panel(s, o, L, font, overlay);
    draw_plot(s, o, L, font, overlay);
    return dl;
}

}  // namespace polyroll::render
