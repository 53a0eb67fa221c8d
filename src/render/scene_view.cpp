// The scene view's draw list: see scene_view.h.
#include "render/scene_view.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "render/close_up.h"
#include "render/world_draw.h"

namespace polyroll::render {


namespace {
// The lanes' numbers and legend: the window's own text (the scene's is render/view_style.h's).
FontSpec lane_font(float unit) { return {FontFace::bold, font_px(20, unit)}; }
}  // namespace

std::vector<FontSpec> scene_view_fonts(float unit) { return {lane_font(unit), scale_font(unit), label_font(unit)}; }

namespace {

// The close-up: bottom left of the view, under the ramp, following one lane's polygon, framed and
// marked in the lane's colour; the main view marks where it looks.
// Its top is kept below the lowest ramp (with its body and labels) where that ramp passes over the
// inset, so with three or four lanes the inset does not hide the start of the lower lanes; it
// shrinks down to a quarter of the view's height for that, and past that it overlaps them.
void draw_lane_close_up(const Snapshot& s, size_t lane, bool racing, const Camera& main_cam, const Snapshot& lowest,
                        const Camera& lowest_cam, const SceneViewOptions& o, const WorldStyle& st,
                        const FontAtlas& font, DrawList& dl, SceneViewBoxes* boxes) {
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
    if (boxes) boxes->close_up.push_back({o.area.x + m, bottom - h, w, h});
    style.marker = lane_colour(lane);
    style.border = lane_colour(lane);
    if (racing) style.label_suffix = fmt::format(", lane {}", lane + 1);
    WorldStyle lane_st = st;
    if (racing) lane_st.shell_wall = lane_colour(lane);
    draw_close_up(s, main_cam, style, lane_st, font, dl);
}

}  // namespace

Rgba lane_colour(size_t lane) { return palette::lanes[lane % palette::lanes.size()]; }

DrawList build_scene_view(const std::vector<Snapshot>& lanes, const SceneViewOptions& o,
                          const FontAtlas& font, SceneViewBoxes* boxes) {
    DrawList dl;
    dl.width_px = o.width_px;
    dl.height_px = o.height_px;
    dl.background = palette::background;
    dl.atlas = &font;
    if (o.area_only) dl.bounds = covering_pixels(o.area);
    if (lanes.empty()) return dl;
    // When racing, each lane's badge sits left of and just above its ramp's upper end: the ramps are
    // fitted into the view less that room, so no badge is cut at the view's edge.
    const bool racing = lanes.size() > 1;
    const FontSpec badge_font = lane_font(o.unit);
    const float badge_pad = 6.0f * o.unit, badge_r = 0.75f * font.line_height(badge_font);
    PxRect fit = o.area;
    if (racing) {
        const float left = 2.0f * badge_r + badge_pad, top = 1.3f * badge_r;
        fit = {o.area.x + left, o.area.y + top, std::max(1.0f, o.area.width - left), std::max(1.0f, o.area.height - top)};
    }
    const LaneLayout layout = lane_layout(lanes, fit, o.follow, o.unit, o.view);
    const ClipRect clip{static_cast<int>(std::floor(o.area.x)), static_cast<int>(std::floor(o.area.y)),
                        static_cast<int>(std::ceil(o.area.width)), static_cast<int>(std::ceil(o.area.height))};
    const WorldStyle st = world_style(o.unit, o.area, o.colouring, o.colour_speed_max_m_s);
    for (size_t i = 0; i < lanes.size(); ++i) {
        WorldStyle lane_st = st;
        if (lanes.size() > 1) lane_st.shell_wall = lane_colour(i);
        draw_world(lanes[i], layout.cameras[i], lane_st, font, dl.new_layer(clip));
    }
    if (boxes)
        for (size_t i = 0; i < lanes.size(); ++i)
            boxes->ramp_starts.push_back(layout.cameras[i].to_px(ramp_to_world({0.0, 0.0}, lanes[i].ramp_angle_deg)));
    if (!o.follow && o.close_up_lane >= 0 && static_cast<size_t>(o.close_up_lane) < lanes.size()) {
        const size_t k = static_cast<size_t>(o.close_up_lane);
        draw_lane_close_up(lanes[k], k, lanes.size() > 1, layout.cameras[k], lanes.back(), layout.cameras.back(), o, st,
                           font, dl, boxes);
    }

    // When racing: each lane's number in a badge at the top of its ramp (where the polygons start); the
    // legend naming each lane is the status band's (sandbox_ui.cpp), above the scene, where it covers
    // no ramp.
    if (racing) {
        Layer& labels_layer = dl.new_layer(clip);
        const float h = font.line_height(badge_font);
        for (size_t i = 0; i < lanes.size(); ++i) {
            const Px top = layout.cameras[i].to_px(ramp_to_world({0.0, 0.0}, lanes[i].ramp_angle_deg));
            const float r = badge_r;
            const Px c{top.x - r - badge_pad, top.y - r * 0.3f};
            labels_layer.shapes.push_back(disc(c, r, lane_colour(i), Tag::none));
            if (boxes) boxes->badges.push_back({c.x - r, c.y - r, 2 * r, 2 * r});
            const std::string num = std::to_string(i + 1);
            font.layout(num, badge_font, {c.x - font.text_width(num, badge_font) / 2.0f, c.y - h / 2.0f + font.ascent(badge_font)},
                        rgb8(255, 255, 255), labels_layer.glyphs);
        }
    }
    return dl;
}

}  // namespace polyroll::render
