// The scene's look, shared by polyroll render's frames and the sandbox's window: line widths and text
// sizes at a design pixel, how the grains are coloured, and the world's style built from them. Both
// draw the same world (world_draw.h) and close-up (close_up.h) with it; only their cameras differ.
#pragma once

#include "render/camera.h"
#include "render/colour.h"
#include "render/font.h"

namespace polyroll::render {

enum class GrainColouring { material, speed };

// A text size of `design_px` design pixels (1 design pixel is 1 pixel at 1280x720) at `unit` pixels
// per design pixel, never below a readable minimum.
int font_px(float design_px, float unit);

// The main line width (the shell's outline, the plot's axes) at `unit`.
float stroke_px(float unit);

// The scene's two text sizes: the ramp scale's labels, and labels over the scene such as the
// close-up's. The frames' overlay uses the same two for its small print and its labels.
FontSpec scale_font(float unit);
FontSpec label_font(float unit);

// The ramp as drawn under its surface, in design pixels: its body (the same thickness at any zoom),
// and the room the body and the scale's labels under it take, which a view leaves free below a ramp.
inline constexpr double kRampBodyDesignPx = 18.0;
inline constexpr float kRampBelowDesignPx = 52.0f;

// How the world is drawn through a camera: everything but the camera itself.
struct WorldStyle {
    float unit = 1.0f;    // design pixel
    float stroke = 2.5f;  // outline width
    FontSpec scale_font;
    PxRect visible;       // only ticks inside this rectangle are drawn
    GrainColouring grain_colouring = GrainColouring::material;
    double colour_speed_max_m_s = 1.0;
    // The shell's wall: the palette's blue, or when several lanes race, each lane's colour, so a
    // polygon is matched to its badge, legend line and readout column at a glance.
    Rgba shell_wall = palette::shell_wall;
};

// The one style builder: the world at `unit`, its ticks kept to `visible`, grains coloured `how`
// (speed: `colour_speed_max_m_s` at the top of the colour map).
WorldStyle world_style(float unit, PxRect visible, GrainColouring how, double colour_speed_max_m_s);

}  // namespace polyroll::render
