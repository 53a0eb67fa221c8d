// Named scene matrices: the sets of scenes a benchmark times, a test checks and a study sweeps, each
// defined once here so the three see the same scenes.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "sim/scene/scene.h"

namespace polyroll::scenes {

// The empty shells on which `--model auto` is measured against the grain model: these side counts on ramps at these angles
// (`polyroll bench --auto` times them; the auto tests check them).
inline constexpr std::array<int, 4> kAutoShellSides{6, 8, 10, 18};
inline constexpr std::array<double, 4> kAutoShellAnglesDeg{5.0, 10.0, 20.0, 30.0};

struct SidesAtAngle {
    int sides = 0;
    double angle_deg = 0.0;
};

// The 16 empty shells, sides first, each side count at every angle.
std::vector<SidesAtAngle> auto_shells();

// `base` emptied (fill ratio 0), with `sides` sides, on a ramp of `angle_deg`: one of the 16 shells.
Scene empty_shell(const Scene& base, int sides, double angle_deg);

// The trade study's scenes (empty, partly filled and full; a small and a large angle; n = 6 and 18;
// BBs and rice), in the order the study runs them.
struct TradeoffScene {
    int sides = 0;
    double fill_ratio = 0.0;
    std::string material;  // a material preset
    double angle_deg = 0.0;
};
std::vector<TradeoffScene> tradeoff_scenes();

// The 2D cross-section's scenes: each shell preset at angles around its thresholds, at each fill ratio.
struct ShellAngles {
    std::string shell;  // a polygon preset
    std::vector<double> angles_deg;
};
const std::vector<ShellAngles>& cross_section_shells();
const std::vector<double>& cross_section_fill_ratios();

}  // namespace polyroll::scenes
