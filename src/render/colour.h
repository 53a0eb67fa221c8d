// Colours of a frame and of the window's panels: one palette for the whole picture (chosen for a
// classroom projector: a light background, dark strokes, saturated fills), grain colours by material,
// and a speed colour map.
#pragma once

#include <array>
#include <string>

namespace polyroll::render {

// Straight (not premultiplied) alpha, components 0..1.
struct Rgba {
    float r = 0.0f, g = 0.0f, b = 0.0f, a = 1.0f;
    bool operator==(const Rgba&) const = default;
};

constexpr Rgba rgb8(int r, int g, int b, float a = 1.0f) {
    return {static_cast<float>(r) / 255.0f, static_cast<float>(g) / 255.0f, static_cast<float>(b) / 255.0f, a};
}

// Every colour of the frames and the window, in one place.
namespace palette {
// The hues the lanes, the curves and the markers are drawn in: saturated and far apart in hue,
// readable on the light background and on a projector.
inline constexpr Rgba red = rgb8(200, 40, 40), blue = rgb8(30, 100, 200), green = rgb8(20, 140, 60),
                      orange = rgb8(200, 120, 0);
inline constexpr Rgba background = rgb8(247, 246, 240);
inline constexpr Rgba ramp_body = rgb8(120, 124, 130);
inline constexpr Rgba ramp_surface = rgb8(30, 32, 36);
inline constexpr Rgba ramp_tick = rgb8(245, 245, 245);
inline constexpr Rgba scale_text = rgb8(60, 62, 66);
inline constexpr Rgba shell_wall = rgb8(38, 94, 170);
inline constexpr Rgba shell_outline = rgb8(12, 30, 70);
inline constexpr Rgba shell_inside = rgb8(222, 231, 242);
inline constexpr Rgba lid_dot = rgb8(0, 0, 0);
inline constexpr Rgba lid_dot_ring = rgb8(255, 255, 255);
inline constexpr Rgba grain_outline = rgb8(40, 36, 30);
inline constexpr Rgba panel_fill = rgb8(255, 255, 255, 0.94f);
inline constexpr Rgba panel_border = rgb8(60, 62, 66);
inline constexpr Rgba text = rgb8(20, 20, 24);
inline constexpr Rgba text_dim = rgb8(85, 88, 95);
inline constexpr Rgba plot_axis = rgb8(60, 62, 66);
inline constexpr Rgba plot_grid = rgb8(215, 215, 210);
inline constexpr Rgba plot_curve = red;
inline constexpr Rgba inset_border = rgb8(60, 62, 66);
inline constexpr Rgba inset_marker = red;
// The window's live plots: a white card in every theme, one colour per lane, one per energy.
inline constexpr Rgba plot_card = rgb8(255, 255, 255);
inline constexpr std::array<Rgba, 4> lanes = {red, blue, green, orange};
inline constexpr Rgba energy_kinetic = red, energy_potential = blue, energy_dissipated = rgb8(70, 70, 70);
// The window's messages on its panels: errors and warnings.
inline constexpr Rgba error_text = {0.75f, 0.05f, 0.05f, 1.0f};
inline constexpr Rgba warning_text = {0.70f, 0.35f, 0.0f, 1.0f};
}  // namespace palette

// Grain fill colour for a material preset: its "look" in assets/materials.json (the file's custom
// colour for grains that are no preset).
Rgba material_colour(const std::string& preset);

// A perceptually ordered map from dark violet (0) through teal to yellow (1); t is clamped.
Rgba speed_colour(double t);

}  // namespace polyroll::render
