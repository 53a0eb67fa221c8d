// The overlay: the panel with the parameters (n, r, theta, material) and the measurements (time,
// speed, distance, face impacts), and the speed-against-time plot that grows as the run proceeds.
#pragma once

#include <string>

#include "render/draw_list.h"
#include "render/font.h"
#include "render/frame_layout.h"
#include "render/snapshot.h"

namespace polyroll::render {

// How the panel names a material preset ("BBs", "peas", ...): its "look" in assets/materials.json.
std::string material_label(const std::string& preset);

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

void draw_plot(const Snapshot& s, const FrameOptions& o, const FrameLayout& L, const FontAtlas& font, Layer& out);

}  // namespace polyroll::render
