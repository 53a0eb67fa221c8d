// The overlay panel and the speed plot: see overlay.h.
#include "render/overlay.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "render/ticks.h"
#include "render/world_draw.h"
#include "sim/assets.h"

namespace polyroll::render {

std::string material_label(const std::string& preset) { return assets::material_look(preset).label; }

namespace {

// A number with a real minus sign, which reads better than a hyphen on a projector.
std::string signed_fixed(double v, int decimals) {
    std::string s = fmt::format("{:.{}f}", std::fabs(v), decimals);
    const bool negative = v < 0.0 && std::stod(s) != 0.0;
    return negative ? "\u2212" + s : s;
}

}  // namespace

std::string params_text(const Snapshot& s) {
    // A full shell reads "full of BBs (r = 1)", as the window's readouts say it.
    const std::string fill = s.fill_ratio >= 1.0 ? fmt::format("full of {} (r = 1)", material_label(s.material))
                             : s.fill_ratio > 0.0 ? fmt::format("r = {:g} {}", s.fill_ratio, material_label(s.material))
                                                  : std::string("empty (r = 0)");
    return fmt::format("n = {}    {}    \u03B8 = {:g}\u00B0", s.sides, fill, s.ramp_angle_deg);
}

std::string signed_value(double v, int decimals) { return signed_fixed(v, decimals); }

void draw_panel(const Snapshot& s, const FrameOptions& o, const FrameLayout& L, const FontAtlas& font, Layer& out) {
    const float u = L.unit;
    PxRect r = L.panel;
    const size_t box_index = out.shapes.size();
    out.shapes.emplace_back();  // the box, sized once the content is measured
    const float pad = 18.0f * u;
    float y = r.y + pad + font.ascent(L.title);
    const std::string params = params_text(s);
    float content_w = font.layout(params, L.title, {r.x + pad, y}, palette::text, out.glyphs);
    // The tracked dot's legend on the same line: the black dot is the lid centre, whose distance
    // and speed the panel and the plot give.
    {
        float lx = r.x + pad + content_w + 26.0f * u;
        const float dot_r = 6.0f * u;
        const Px c{lx + dot_r, y - font.ascent(L.label) * 0.35f};
        out.shapes.push_back(disc(c, dot_r + std::max(1.0f, 1.5f * u), palette::lid_dot_ring, Tag::panel));
        out.shapes.push_back(disc(c, dot_r, palette::lid_dot, Tag::panel));
        lx += 2.0f * dot_r + 8.0f * u;
        lx += font.layout("lid centre (measured)", L.label, {lx, y}, palette::text_dim, out.glyphs);
        content_w = lx - (r.x + pad);
    }

    // Four columns, each as wide as its widest possible value, so nothing jumps between frames.
    struct Column {
        const char* label;
        std::string value;
        const char* widest;
    };
    // In slow motion the time column says so: the clock shows simulated time, slower than the video's.
    const std::string time_label =
        o.slow_motion > 1 ? fmt::format("time ({}\u00D7 slower)", o.slow_motion) : std::string("time");
    const Column cols[4] = {{time_label.c_str(), fmt::format("{:.2f} s", s.time_s), "00.00 s"},
                            {"speed", signed_fixed(s.now.speed_m_s, 2) + " m/s", "\u22120.00 m/s"},
                            {"distance", signed_fixed(s.now.position_m, 3) + " m", "0.000 m"},
                            {"face impacts", fmt::format("{}", s.impacts), "000"}};
    const float label_y = y + 16.0f * u + font.ascent(L.label);
    const float value_y = label_y + 8.0f * u + font.ascent(L.value);
    const float gap = 30.0f * u;
    float x = r.x + pad;
    for (const Column& c : cols) {
        font.layout(c.label, L.label, {x, label_y}, palette::text_dim, out.glyphs);
        font.layout(c.value, L.value, {x, value_y}, palette::text, out.glyphs);
        x += std::max(font.text_width(c.widest, L.value), font.text_width(c.label, L.label)) + gap;
    }
    content_w = std::max(content_w, x - gap - (r.x + pad));

    if (o.grain_colouring == GrainColouring::speed) {
        // The colour map's legend: a bar from 0 to the top speed.
        const float bar_y = value_y + 22.0f * u;
        const std::string left = "grain speed  0";
        float bx = r.x + pad;
        const float text_base = bar_y + font.ascent(L.label) * 0.8f;
        bx += font.layout(left, L.label, {bx, text_base}, palette::text_dim, out.glyphs) + 10.0f * u;
        const int steps = 24;
        const float bar_w = 220.0f * u, bar_h = 16.0f * u, step_w = bar_w / steps;
        for (int i = 0; i < steps; ++i) {
            const Rgba c = speed_colour((i + 0.5) / steps);
            out.shapes.push_back(rounded_box({bx + i * step_w, bar_y}, {step_w + 0.5f, bar_h}, 0.0f, c, 0.0f, c,
                                             Tag::panel));
        }
        bx += bar_w + 10.0f * u;
        bx += font.layout(fmt::format("{:g} m/s", o.colour_speed_max_m_s), L.label, {bx, text_base},
                          palette::text_dim, out.glyphs);
        content_w = std::max(content_w, bx - (r.x + pad));
    }
    r.width = std::max(r.width, content_w + 2.0f * pad);
    out.shapes[box_index] = rounded_box({r.x, r.y}, {r.width, r.height}, 10.0f * u, palette::panel_fill,
                                        std::max(1.0f, 1.5f * u), palette::panel_border, Tag::panel);
}

void draw_outcome(const FrameOptions& o, const FrameLayout& L, const FontAtlas& font, Layer& out) {
    if (o.outcome.empty()) return;
    const float u = L.unit;
    const float pad = 16.0f * u;
    const float tw = font.text_width(o.outcome, L.value);
    const float w = tw + 2.0f * pad, h = font.line_height(L.value) + 1.5f * pad;
    // Centred across the frame, just below the panel and the plot.
    const float top = std::max(L.panel.y + L.panel.height, L.plot.y + L.plot.height) + 14.0f * u;
    const float x = (static_cast<float>(o.width_px) - w) / 2.0f;
    out.shapes.push_back(rounded_box({x, top}, {w, h}, 10.0f * u, palette::panel_fill, std::max(1.5f, 2.5f * u),
                                     palette::plot_curve, Tag::panel));
    font.layout(o.outcome, L.value, {x + pad, top + 0.75f * pad + font.ascent(L.value)}, palette::text, out.glyphs);
}

PlotAxes plot_axes(const Snapshot& s, const FrameOptions& o) {
    PlotAxes a;
    double t_hi = 0.0, v_lo = 0.0, v_hi = 0.0;
    for (const SpeedPoint& p : s.speed_history) {
        t_hi = std::max(t_hi, p.time_s);
        v_lo = std::min(v_lo, p.speed_m_s);
        v_hi = std::max(v_hi, p.speed_m_s);
    }
    // Not fixed: grown as the window's plots grow.
    const PlotAxes grown = growing_speed_axes(t_hi, v_lo, v_hi);
    a.time_max_s = o.plot_time_max_s ? *o.plot_time_max_s : grown.time_max_s;
    a.speed_max_m_s = o.plot_speed_max_m_s ? *o.plot_speed_max_m_s : grown.speed_max_m_s;
    a.speed_min_m_s = o.plot_speed_min_m_s ? *o.plot_speed_min_m_s : grown.speed_min_m_s;
    return a;
}

PlotAxes growing_speed_axes(double t_hi_s, double v_lo_m_s, double v_hi_m_s) {
    const AxisRange v = growing_value_axis(v_lo_m_s, v_hi_m_s, kSpeedAxisFloor_m_s, kSpeedAxisFloorBelow_m_s);
    return {growing_time_axis_s(t_hi_s), v.lo, v.hi};
}

void draw_plot(const Snapshot& s, const FrameOptions& o, const FrameLayout& L, const FontAtlas& font, Layer& out) {
    draw_speed_plot({{&s.speed_history, palette::plot_curve}}, plot_axes(s, o), L, font, out);
}

void draw_speed_plot(const std::vector<PlotTrace>& traces, const PlotAxes& ax, const FrameLayout& L,
                     const FontAtlas& font, Layer& out) {
    const float u = L.unit;
    const PxRect& r = L.plot;
    out.shapes.push_back(rounded_box({r.x, r.y}, {r.width, r.height}, 10.0f * u, palette::panel_fill,
                                     std::max(1.0f, 1.5f * u), palette::panel_border, Tag::panel));
    const float pad = 14.0f * u;
    font.layout("speed along the ramp, m/s", L.label, {r.x + pad, r.y + pad + font.ascent(L.label)}, palette::text,
                out.glyphs);
    // The data area, leaving room for the tick labels.
    const float left = r.x + 62.0f * u, right = r.x + r.width - 34.0f * u;
    const float top = r.y + pad + font.line_height(L.label) + 10.0f * u;
    const float bottom = r.y + r.height - 32.0f * u;
    const PlotMapping map{left, right, top, bottom, ax.time_max_s, ax.speed_min_m_s, ax.speed_max_m_s};
    auto X = [&](double t) { return map.x(t); };
    auto Y = [&](double v) { return map.y(v); };
    const float thin = std::max(1.0f, 1.2f * u);
    // Grid and tick labels: about four intervals on the speed axis, five on the time axis.
    const AxisTicks v_ticks = axis_ticks(ax.speed_min_m_s, ax.speed_max_m_s, 4.0);
    for (int k = 0; k < v_ticks.count; ++k) {
        const double v = v_ticks.at(k);
        const float y = Y(v);
        out.shapes.push_back(segment({left, y}, {right, y}, thin, palette::plot_grid, Tag::plot));
        const std::string label = signed_fixed(std::fabs(v) < 1e-12 ? 0.0 : v, v_ticks.step < 0.1 ? 2 : 1);
        const float tw = font.text_width(label, L.small);
        font.layout(label, L.small, {left - 8.0f * u - tw, y + font.ascent(L.small) * 0.35f}, palette::text_dim,
                    out.glyphs);
    }
    const AxisTicks t_ticks = axis_ticks(0.0, ax.time_max_s, 5.0);
    for (int k = 0; k < t_ticks.count; ++k) {
        const double t = t_ticks.at(k);
        const float x = X(t);
        out.shapes.push_back(segment({x, top}, {x, bottom}, thin, palette::plot_grid, Tag::plot));
        // The unit rides on the last label, where a separate one would collide with it.
        const bool last = k + 1 == t_ticks.count;
        const std::string label = fmt::format("{:g}{}", std::round(t * 1000.0) / 1000.0, last ? " s" : "");
        const float tw = font.text_width(last ? label.substr(0, label.size() - 2) : label, L.small);
        font.layout(label, L.small, {x - tw / 2.0f, bottom + 6.0f * u + font.ascent(L.small)}, palette::text_dim,
                    out.glyphs);
    }
    out.shapes.push_back(segment({left, bottom}, {right, bottom}, L.stroke * 0.7f, palette::plot_axis, Tag::plot));
    out.shapes.push_back(segment({left, top}, {left, bottom}, L.stroke * 0.7f, palette::plot_axis, Tag::plot));
    if (ax.speed_min_m_s < 0.0)
        out.shapes.push_back(segment({left, Y(0.0)}, {right, Y(0.0)}, thin, palette::plot_axis, Tag::plot));

    // Each curve so far, as a polyline of round-capped segments; a dot marks the present.
    const float curve = std::max(1.5f, 3.0f * u);
    for (const PlotTrace& trace : traces) {
        const std::vector<SpeedPoint>& h = *trace.history;
        for (size_t i = 1; i < h.size(); ++i) {
            if (h[i].time_s > ax.time_max_s) break;
            out.shapes.push_back(segment({X(h[i - 1].time_s), Y(h[i - 1].speed_m_s)},
                                         {X(h[i].time_s), Y(h[i].speed_m_s)}, curve, trace.colour, Tag::plot));
        }
        if (!h.empty() && h.back().time_s <= ax.time_max_s)
            out.shapes.push_back(disc({X(h.back().time_s), Y(h.back().speed_m_s)}, 2.2f * curve, trace.colour,
                                      Tag::plot));
    }
}

}  // namespace polyroll::render
