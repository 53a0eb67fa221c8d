// The scene view's draw list: see scene_view.h.
#include "app/scene_view.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "render/close_up.h"
#include "render/world_draw.h"

namespace polyroll::app {

using namespace render;

namespace {
// The lanes' numbers and legend: the window's own text (the scene's is render/view_style.h's).
FontSpec lane_font(float unit) { return {FontFace::bold, font_px(20, unit)}; }
}  // namespace

std::vector<FontSpec> scene_view_fonts(float unit) { return {lane_font(unit), scale_font(unit), label_font(unit)}; }

namespace {

// The close-up: bottom left of the view, under the ramp, following one lane's polygon, framed and
// marked in the lane's colour; the main view marks where it looks.
// Its top is kept below the lowest ramp (with its body and labels) where that ramp passes over the
// inset, so with three or four lanes the inset no longer hides the start of the lower lanes; it
// shrinks down to a quarter of the view's height for that, and past it overlaps as before.
void draw_lane_close_up(const Snapshot& s, size_t lane, bool racing, const Camera& main_cam, const Snapshot& lowest,
                        const Camera& lowest_cam, const SceneViewOptions& o, const WorldStyle& st,
                        const FontAtlas& font, DrawList& dl) {
    const float u = o.unit;
    const float m = 12.0f * u;
    const float w = std::round(0.36f * o.area.width);
    const float bottom = o.area.y + o.area.height - m;
    const Px a = lowest_cam.to_px(ramp_to_world({0.0, 0.0}, lowest.ramp_angle_deg));
    const Px b = lowest_cam.to_px(ramp_to_world({lowest.ramp_length_m, 0.0}, lowest.ramp_angle_deg));
    const float x = std::clamp(o.area.x + m + w, std::min(a.x, b.x), std::max(a.x, b.x));
    const float ramp_y = std::fabs(b.x - a.x) > 1e-3f ? a.y + (x - a.x) * (b.y - a.y) / (b.x - a.x) : std::max(a.y, b.y);
    const float clear_top = ramp_y + render::kRampBelowDesignPx * u + m;
    const float h = std::round(std::clamp(bottom - clear_top, 0.25f * o.area.height, 0.50f * o.area.height));
    CloseUpStyle style = close_up_style({o.area.x + m, bottom - h, w, h}, u);
    style.marker = lane_colour(lane);
    style.border = lane_colour(lane);
    if (racing) style.label_suffix = fmt::format(", lane {}", lane + 1);
    WorldStyle lane_st = st;
    if (racing) lane_st.shell_wall = lane_colour(lane);
    draw_close_up(s, main_cam, style, lane_st, font, dl);
}

}  // namespace

Rgba lane_colour(size_t lane) {
    // Saturated and far apart in hue, readable on the light background and on a projector.
    static constexpr Rgba colours[] = {rgb8(200, 40, 40), rgb8(30, 100, 200), rgb8(20, 140, 60), rgb8(200, 120, 0)};
    return colours[lane % 4];
}

DrawList build_scene_view(const std::vector<Snapshot>& lanes, const std::vector<std::string>& labels,
                          const SceneViewOptions& o, const FontAtlas& font) {
    DrawList dl;
    dl.width_px = o.width_px;
    dl.height_px = o.height_px;
    dl.background = palette::background;
    dl.atlas = &font;
    if (lanes.empty()) return dl;
    const LaneLayout layout = lane_layout(lanes, o.area, o.follow, o.unit, o.view);
    const ClipRect clip{static_cast<int>(std::floor(o.area.x)), static_cast<int>(std::floor(o.area.y)),
                        static_cast<int>(std::ceil(o.area.width)), static_cast<int>(std::ceil(o.area.height))};
    const WorldStyle st = world_style(o.unit, o.area, o.colouring, o.colour_speed_max_m_s);
    for (size_t i = 0; i < lanes.size(); ++i) {
        WorldStyle lane_st = st;
        if (lanes.size() > 1) lane_st.shell_wall = lane_colour(i);
        draw_world(lanes[i], layout.cameras[i], lane_st, font, dl.new_layer(clip));
    }
    if (!o.follow && o.close_up_lane >= 0 && static_cast<size_t>(o.close_up_lane) < lanes.size()) {
        const size_t k = static_cast<size_t>(o.close_up_lane);
        draw_lane_close_up(lanes[k], k, lanes.size() > 1, layout.cameras[k], lanes.back(), layout.cameras.back(), o, st,
                           font, dl);
    }

    // When racing: each lane's number in a badge at the top of its ramp (where the polygons start),
    // and a legend in the free corner above the ramps naming each lane.
    if (lanes.size() > 1) {
        Layer& labels_layer = dl.new_layer(clip);
        const FontSpec f = lane_font(o.unit);
        const float pad = 6.0f * o.unit;
        const float h = font.line_height(f);
        float legend_w = 0.0f;
        for (size_t i = 0; i < lanes.size() && i < labels.size(); ++i)
            legend_w = std::max(legend_w, font.text_width(std::to_string(i + 1) + "  " + labels[i], f));
        const float lx = o.area.x + o.area.width - legend_w - 3.0f * pad;
        float ly = o.area.y + pad;
        labels_layer.shapes.push_back(rounded_box({lx - pad, ly - pad / 2}, {legend_w + 2 * pad, h * static_cast<float>(lanes.size()) + pad},
                                                  4.0f * o.unit, rgb8(255, 255, 255, 0.92f), std::max(1.0f, 1.5f * o.unit),
                                                  palette::panel_border));
        for (size_t i = 0; i < lanes.size() && i < labels.size(); ++i) {
            font.layout(std::to_string(i + 1) + "  " + labels[i], f, {lx, ly + font.ascent(f)}, lane_colour(i),
                        labels_layer.glyphs);
            ly += h;
            // The badge, left of the ramp's upper end.
            const Px top = layout.cameras[i].to_px(ramp_to_world({0.0, 0.0}, lanes[i].ramp_angle_deg));
            const float r = 0.75f * h;
            const Px c{top.x - r - pad, top.y - r * 0.3f};
            labels_layer.shapes.push_back(disc(c, r, lane_colour(i), Tag::none));
            const std::string num = std::to_string(i + 1);
            font.layout(num, f, {c.x - font.text_width(num, f) / 2.0f, c.y - h / 2.0f + font.ascent(f)},
                        rgb8(255, 255, 255), labels_layer.glyphs);
        }
    }
    return dl;
}

}  // namespace polyroll::app
