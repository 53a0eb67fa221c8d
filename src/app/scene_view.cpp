// The scene view's draw list: see scene_view.h.
#include "app/scene_view.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "render/world_draw.h"

namespace polyroll::app {

using namespace render;

namespace {
FontSpec label_font(float unit) { return {FontFace::bold, std::max(8, static_cast<int>(std::lround(20.0f * unit)))}; }
FontSpec inset_font(float unit) { return {FontFace::regular, std::max(8, static_cast<int>(std::lround(18.0f * unit)))}; }
FontSpec scale_font(float unit) { return {FontFace::regular, std::max(7, static_cast<int>(std::lround(16.0f * unit)))}; }
}  // namespace

std::vector<FontSpec> scene_view_fonts(float unit) { return {label_font(unit), scale_font(unit), inset_font(unit)}; }

namespace {

double outer_radius_m(const Snapshot& s) {
    double r = 0.0;
    for (const geom::Vec2& v : s.outer_local_m) r = std::max(r, geom::length(v));
    return r;
}

void outline(Layer& out, PxRect r, float width, Rgba colour, Tag tag) {
    const Px tl{r.x, r.y}, tr{r.x + r.width, r.y}, br{r.x + r.width, r.y + r.height}, bl{r.x, r.y + r.height};
    out.shapes.push_back(segment(tl, tr, width, colour, tag));
    out.shapes.push_back(segment(tr, br, width, colour, tag));
    out.shapes.push_back(segment(br, bl, width, colour, tag));
    out.shapes.push_back(segment(bl, tl, width, colour, tag));
}

// Share of the inset's height the polygon's outer radius spans (as polyroll render's close-up).
constexpr double kInsetRadiusShare = 0.30;

// The close-up: bottom left of the view, under the ramp, following one lane's polygon; the main
// view marks where it looks.
void draw_close_up(const Snapshot& s, size_t lane, bool racing, const Camera& main_cam, const SceneViewOptions& o, const WorldStyle& st,
                   const FontAtlas& font, DrawList& dl) {
    const float u = o.unit;
    const float m = 12.0f * u;
    const float w = std::round(0.36f * o.area.width), h = std::round(0.50f * o.area.height);
    const PxRect r{o.area.x + m, o.area.y + o.area.height - h - m, w, h};
    const double R = outer_radius_m(s);
    const Camera cam = follow_camera(s.shell_centre_m, s.ramp_angle_deg, R, kInsetRadiusShare, r);
    {
        Layer& mark = dl.new_layer();
        const Px c = main_cam.to_px(ramp_to_world(s.shell_centre_m, s.ramp_angle_deg));
        const float half = std::max(8.0f * u, main_cam.to_px_length(R) * 1.6f);
        outline(mark, {c.x - half, c.y - half, 2 * half, 2 * half}, std::max(1.0f, 2.0f * u), lane_colour(lane),
                Tag::inset_marker);
    }
    const ClipRect clip{static_cast<int>(std::lround(r.x)), static_cast<int>(std::lround(r.y)),
                        static_cast<int>(std::lround(r.width)), static_cast<int>(std::lround(r.height))};
    Layer& back = dl.new_layer(clip);
    const Px tl{r.x, r.y}, tr{r.x + r.width, r.y}, br{r.x + r.width, r.y + r.height}, bl{r.x, r.y + r.height};
    back.triangles.push_back({tl, tr, br, palette::background, Tag::inset_frame});
    back.triangles.push_back({tl, br, bl, palette::background, Tag::inset_frame});
    WorldStyle inset_style = st;
    inset_style.visible = r;
    draw_world(s, cam, inset_style, font, dl.new_layer(clip));
    Layer& frame = dl.new_layer();
    outline(frame, r, std::max(1.0f, 2.5f * u), lane_colour(lane), Tag::inset_frame);
    const FontSpec f = inset_font(u);
    const std::string text = fmt::format("close-up \u00D7{:.0f}{}", cam.px_per_m / main_cam.px_per_m,
                                         racing ? fmt::format(", lane {}", lane + 1) : std::string());
    font.layout(text, f, {r.x + 8.0f * u, r.y + 6.0f * u + font.ascent(f)}, palette::text_dim, frame.glyphs);
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
    WorldStyle st;
    st.unit = o.unit;
    st.stroke = std::max(1.0f, 2.5f * o.unit);
    st.scale_font = scale_font(o.unit);
    st.visible = o.area;
    st.grain_colouring = o.colouring;
    st.colour_speed_max_m_s = o.colour_speed_max_m_s;
    for (size_t i = 0; i < lanes.size(); ++i) draw_world(lanes[i], layout.cameras[i], st, font, dl.new_layer(clip));
    if (!o.follow && o.close_up_lane >= 0 && static_cast<size_t>(o.close_up_lane) < lanes.size()) {
        const size_t k = static_cast<size_t>(o.close_up_lane);
        draw_close_up(lanes[k], k, lanes.size() > 1, layout.cameras[k], o, st, font, dl);
    }

    // When racing: each lane's number in a badge at the top of its ramp (where the polygons start),
    // and a legend in the free corner above the ramps naming each lane.
    if (lanes.size() > 1) {
        Layer& labels_layer = dl.new_layer(clip);
        const FontSpec f = label_font(o.unit);
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
