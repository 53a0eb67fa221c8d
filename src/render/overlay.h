// The overlay: the panel with the parameters (n, r, theta, material) and the measurements (time,
// speed, distance, face impacts), and the speed-against-time plot that grows as the run proceeds;
// the speed plot's axes and mapping are the window's live plot's too. No GL, no ImGui.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "render/draw_list.h"
#include "render/font.h"
#include "render/frame_layout.h"
#include "render/snapshot.h"

namespace polyroll::render {

// How the panel names a material preset ("BBs", "peas", ...): its "look" in assets/materials.json.
std::string material_label(const std::string& preset);

// The panel's parameter line: "n = 6    r = 0.5 BBs    \u03B8 = 14\u00B0".
std::string params_text(const Snapshot& s);
// A number with a real minus sign ("\u22120.12"), as the panel writes speeds and distances.
std::string signed_value(double v, int decimals);

void draw_panel(const Snapshot& s, const FrameOptions& o, const FrameLayout& L, const FontAtlas& font, Layer& out);

// The outcome banner (FrameOptions::outcome), centred below the panel; nothing when it is empty.
void draw_outcome(const FrameOptions& o, const FrameLayout& L, const FontAtlas& font, Layer& out);

// The plot's axis ranges for a snapshot: the options' fixed values, or grown to fit the data.
struct PlotAxes {
    double time_max_s = 1.0;
    double speed_min_m_s = 0.0;
    double speed_max_m_s = 0.1;
};
PlotAxes plot_axes(const Snapshot& s, const FrameOptions& o);

// The speed plots' axes, the frames' and the window's live one (app/sandbox_ui.cpp): grown to hold
// times up to t_hi_s and speeds in [v_lo_m_s, v_hi_m_s] and 0, in readable steps (ticks.h).
PlotAxes growing_speed_axes(double t_hi_s, double v_lo_m_s, double v_hi_m_s);

// Where a plot's data area puts a sample, for the frames' plot and the window's: time from 0 to
// t_max_s across [left, right], values from lo to hi up [bottom, top] (clamped to the axis).
struct PlotMapping {
    float left = 0, right = 0, top = 0, bottom = 0;
    double t_max_s = 1.0, lo = 0.0, hi = 1.0;
    float x(double t_s) const { return left + static_cast<float>(t_s / t_max_s) * (right - left); }
    float y(double v) const {
        const double c = std::clamp(v, lo, hi);
        return bottom - static_cast<float>((c - lo) / std::max(hi - lo, 1e-9)) * (bottom - top);
    }
};

void draw_plot(const Snapshot& s, const FrameOptions& o, const FrameLayout& L, const FontAtlas& font, Layer& out);

// The same plot in the layout's plot box with several curves (a race: one per lane, in its colour).
struct PlotTrace {
    const std::vector<SpeedPoint>* history = nullptr;
    Rgba colour;
};
void draw_speed_plot(const std::vector<PlotTrace>& traces, const PlotAxes& ax, const FrameLayout& L,
                     const FontAtlas& font, Layer& out);

}  // namespace polyroll::render
