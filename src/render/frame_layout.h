// Where things go in a frame of a given size: the overlay panel, the plot, the area the ramp is
// fitted into, the close-up inset, the font sizes and line widths. Sized for a classroom projector:
// everything scales with the frame, from a 1280x720 design.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "render/camera.h"
#include "render/font.h"
#include "render/view_style.h"

namespace polyroll::render {

// What the user chooses about a frame.
struct FrameOptions {
    int width_px = 1280;
    int height_px = 720;
    bool follow = false;  // the camera follows the shell instead of showing the whole ramp
    GrainColouring grain_colouring = GrainColouring::material;
    double colour_speed_max_m_s = 1.0;  // grain speed at the top of the colour map
    // The plot's axes: fixed when the run's extent is known in advance (a render: options_for_run),
    // otherwise they grow with the data as the sandbox's plots do (render/ticks.h).
    std::optional<double> plot_time_max_s;
    std::optional<double> plot_speed_min_m_s;
    std::optional<double> plot_speed_max_m_s;
    // Frames per simulated second over real time: above 1 the panel marks the slow motion
    // ("4\u00D7 slower"), so a viewer does not take a slowed run for a slow polygon.
    int slow_motion = 1;
    // The run's outcome in words ("stopped after 0.14 m", "rolled to the end"), shown as a banner
    // over the world on the final, held frames; empty on the frames before.
    std::string outcome;
};

struct FrameLayout {
    float unit = 1.0f;  // pixels per design pixel (1 at 1280x720)
    float margin = 16.0f;
    PxRect panel;       // parameters and measurements, top left
    PxRect plot;        // speed against time, top right
    PxRect world;       // what the main camera frames
    std::optional<PxRect> inset;  // the close-up of the shell (whole-ramp view only)
    FontSpec title, label, value, small;
    float stroke = 2.0f;  // the main line width
};

FrameLayout frame_layout(const FrameOptions& o);

// Every font size a frame of these options uses: the atlas must hold them.
std::vector<FontSpec> frame_fonts(const FrameOptions& o);

}  // namespace polyroll::render
