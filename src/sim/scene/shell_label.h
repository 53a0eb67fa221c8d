// The shell named for what it is. A polygon preset with --sides changed is no longer that preset:
// `--sides 8` on hexagon-small printed "hexagon-small (n = 8)". The label says the shape
// and where its other dimensions came from: "octagon (n = 8) with hexagon-small's size, walls and mass".
#pragma once

#include <string>

#include "sim/scene/scene.h"

namespace polyroll {

// "hexagon", "octagon", "octadecagon", ...; "n-gon" spelt with the number for the rest ("13-gon").
std::string polygon_name(int sides);

// "hexagon-small (n = 6)" when the shell is its preset's values; "octagon (n = 8) with
// hexagon-small's size, walls and mass" when only the sides differ; "custom octagon (n = 8), from
// hexagon-small" when more differs; "custom octagon (n = 8)" without a preset.
std::string shell_label(const Scene& scene);

// Whether a shell named for a polygon preset has that preset's own n (false without a preset, or
// for another n; true for a preset the assets no longer have, whose values are all there is): the
// window's polygon box and results.csv's polygon column say "custom" otherwise.
bool has_presets_sides(const ShellParams& shell);

}  // namespace polyroll
