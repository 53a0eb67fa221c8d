// A race's frame: see race_frame.h.
#include "render/race_frame.h"

#include <algorithm>

#include <fmt/core.h>

#include "render/overlay.h"
#include "render/scene_view.h"
#include "render/view_style.h"

namespace polyroll::render {

std::string race_outcome_text(Behaviour b) {
    switch (b) {
        case Behaviour::stopped_at_first_impact: return "stopped at its first impact";
        case Behaviour::stopped: return "stopped";
        case Behaviour::rolled_to_end: return "rolled to the end";
        case Behaviour::time_limit: return "time limit reached";
        case Behaviour::diverged: return "diverged";
        case Behaviour::running: return "";
    }
    return "";
}

namespace {

// The panel: the time, then one row per lane: its badge, its parameters, its distance and face
// impacts, and its speed (or, on the held frames, its ending). Returns its box.
PxRect draw_race_panel(const std::vector<Snapshot>& lanes, const FrameOptions& o, const FrameLayout& L,
                      const std::vector<std::string>& outcomes, const FontAtlas& font, Layer& out) {
    const float u = L.unit;
    const float pad = 14.0f * u;
    const size_t box_index = out.shapes.size();
    out.shapes.emplace_back();  // the box, sized once the content is measured
    const PxRect r = L.panel;
    float y = r.y + pad + font.ascent(L.title);
    const std::string time_label =
        o.slow_motion > 1 ? fmt::format("   ({}\u00D7 slower)", o.slow_motion) : std::string();
    float content_w = font.layout(fmt::format("race of {} lanes    time {:.2f} s{}", lanes.size(),
                                              lanes.empty() ? 0.0 : lanes.front().time_s, time_label),
                                  L.title, {r.x + pad, y}, palette::text, out.glyphs);
    // Columns as wide as their widest possible value, so nothing jumps between frames.
    float params_w = 0.0f;
    for (const Snapshot& s : lanes) params_w = std::max(params_w, font.text_width(params_text(s), L.label));
    const float badge_r = 0.62f * font.line_height(L.label);
    const float gap = 22.0f * u;
    float last_w = font.text_width("\u22120.00 m/s", L.label);
    for (Behaviour b : {Behaviour::stopped_at_first_impact, Behaviour::stopped, Behaviour::rolled_to_end,
                        Behaviour::time_limit, Behaviour::diverged})
        last_w = std::max(last_w, font.text_width(race_outcome_text(b), L.label));
    const float row_h = std::max(2.0f * badge_r, font.line_height(L.label)) + 8.0f * u;
    y += 10.0f * u;
    for (size_t i = 0; i < lanes.size(); ++i) {
        const Snapshot& s = lanes[i];
        const float base = y + row_h - 4.0f * u - (row_h - font.line_height(L.label)) / 2.0f;
        const Px c{r.x + pad + badge_r, y + row_h / 2.0f};
        out.shapes.push_back(disc(c, badge_r, lane_colour(i), Tag::panel));
        const std::string num = std::to_string(i + 1);
        font.layout(num, L.label, {c.x - font.text_width(num, L.label) / 2.0f, base}, rgb8(255, 255, 255), out.glyphs);
        float x = r.x + pad + 2.0f * badge_r + 10.0f * u;
        font.layout(params_text(s), L.label, {x, base}, palette::text, out.glyphs);
        x += params_w + gap;
        const std::string distance = signed_value(s.now.position_m, 3) + " m";
        font.layout(distance, L.label, {x + font.text_width("0.000 m", L.label) - font.text_width(distance, L.label), base},
                    palette::text, out.glyphs);
        x += font.text_width("0.000 m", L.label) + gap;
        const std::string impacts = fmt::format("{} impact{}", s.impacts, s.impacts == 1 ? "" : "s");
        font.layout(impacts, L.label, {x, base}, palette::text_dim, out.glyphs);
        x += font.text_width("000 impacts", L.label) + gap;
        // The speed while running, the ending on the held frames: the column as wide as the widest
        // of them, so the panel (and the plot beside it) keeps its size from the first frame to the last.
        const bool ended = i < outcomes.size() && !outcomes[i].empty();
        const std::string last = ended ? outcomes[i] : signed_value(s.now.speed_m_s, 2) + " m/s";
        font.layout(last, L.label, {x, base}, ended ? palette::text : palette::text_dim, out.glyphs);
        x += last_w;
        content_w = std::max(content_w, x - (r.x + pad));
        y += row_h;
    }
    const PxRect box{r.x, r.y, content_w + 2.0f * pad, y + pad - 4.0f * u - r.y};
    out.shapes[box_index] = rounded_box({box.x, box.y}, {box.width, box.height}, 10.0f * u, palette::panel_fill,
                                        std::max(1.0f, 1.5f * u), palette::panel_border, Tag::panel);
    return box;
}

}  // namespace

std::vector<FontSpec> race_frame_fonts(const FrameOptions& o) {
    std::vector<FontSpec> fonts = frame_fonts(o);
    for (const FontSpec& f : scene_view_fonts(frame_layout(o).unit)) fonts.push_back(f);
    return fonts;
}

DrawList build_race_frame(const std::vector<Snapshot>& lanes, const FrameOptions& o,
                          const std::vector<std::string>& outcomes, const FontAtlas& font) {
    const FrameLayout L = frame_layout(o);
    const float w = static_cast<float>(o.width_px), h = static_cast<float>(o.height_px);
    // The panel and the plot first, to know where the lanes may start: the overlay is drawn after.
    DrawList overlay_list;
    Layer& overlay = overlay_list.new_layer();
    const PxRect panel = draw_race_panel(lanes, o, L, outcomes, font, overlay);
    const float panel_bottom = panel.y + panel.height;
    FrameLayout plot_layout = L;
    // The plot beside the panel, as tall as it (at least the frames' plot height), in the width the
    // panel leaves (a narrower plot than a single run's frame, if need be).
    plot_layout.plot.height = std::max(L.plot.height, panel_bottom - L.plot.y);
    const float plot_left = std::max(L.plot.x, panel.x + panel.width + L.margin);
    plot_layout.plot.width = std::max(1.0f, L.plot.x + L.plot.width - plot_left);
    plot_layout.plot.x = plot_left;
    PlotAxes axes;
    axes.time_max_s = o.plot_time_max_s.value_or(1.0);
    axes.speed_min_m_s = o.plot_speed_min_m_s.value_or(0.0);
    axes.speed_max_m_s = o.plot_speed_max_m_s.value_or(1.0);
    std::vector<PlotTrace> traces;
    for (size_t i = 0; i < lanes.size(); ++i) traces.push_back({&lanes[i].speed_history, lane_colour(i)});
    draw_speed_plot(traces, axes, plot_layout, font, overlay);

    // The lanes, as the window lays them out, in the frame under the panel and the plot.
    SceneViewOptions v;
    v.width_px = o.width_px;
    v.height_px = o.height_px;
    const float top = std::max(panel_bottom, plot_layout.plot.y + plot_layout.plot.height) + L.margin;
    v.area = {L.margin, top, std::max(1.0f, w - 2.0f * L.margin), std::max(1.0f, h - top - L.margin)};
    v.unit = L.unit;
    v.follow = o.follow;
    v.colouring = o.grain_colouring;
    v.colour_speed_max_m_s = o.colour_speed_max_m_s;
    v.close_up_lane = 0;
    DrawList dl = build_scene_view(lanes, v, font);
    dl.layers.push_back(std::move(overlay));
    return dl;
}

}  // namespace polyroll::render
