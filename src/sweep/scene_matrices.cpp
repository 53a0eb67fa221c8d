// Named scene matrices: see scene_matrices.h.
#include "sweep/scene_matrices.h"

namespace polyroll::scenes {

std::vector<SidesAtAngle> auto_shells() {
    std::vector<SidesAtAngle> out;
    for (int sides : kAutoShellSides)
        for (double angle : kAutoShellAnglesDeg) out.push_back({sides, angle});
    return out;
}

Scene empty_shell(const Scene& base, int sides, double angle_deg) {
    Scene s = base;
    s.fill.ratio = 0.0;
    s.shell.sides = sides;
    s.ramp.angle_deg = angle_deg;
    return s;
}

std::vector<TradeoffScene> tradeoff_scenes() {
    const std::vector<int> sides = {6, 18};
    const std::vector<std::pair<double, std::string>> fills = {
        {0.0, "bb"}, {0.5, "bb"}, {1.0, "bb"}, {0.5, "rice"}, {1.0, "rice"}};
    // 12 degrees: below the rolling band of the filled hexagons; 24: above it (the sweep in
    // docs/sweeps.md). Plus the third behaviour's scene, the half-full BB hexagon at 20 degrees.
    const std::vector<double> angles = {12.0, 24.0};
    std::vector<TradeoffScene> out;
    for (int n : sides)
        for (const auto& [r, material] : fills)
            for (double a : angles) out.push_back({n, r, material, a});
    out.push_back({6, 0.5, "bb", 20.0});
    return out;
}

const std::vector<ShellAngles>& cross_section_shells() {
    // Angles around each shell's thresholds, as a first 3D prototype found them (the hexagon a quarter
    // full: first impact at 17 deg, rolling from 18; the octagon 0.375 full: a few faces at 12-13,
    // rolling from 14), reaching a few degrees either side for the other fills.
    static const std::vector<ShellAngles> shells = {
        {"hexagon-small", {14, 16, 17, 18, 19, 20, 22}},
        {"octagon-small", {9, 11, 12, 13, 14, 15, 17}},
    };
    return shells;
}

const std::vector<double>& cross_section_fill_ratios() {
    static const std::vector<double> fills = {0.25, 0.375, 0.5};
    return fills;
}

}  // namespace polyroll::scenes
