// Where the grains go before release: circles packed in the bulk region of the fill (the part of
// the inside below a level free surface holding fraction r of the inside area), in the shell's own
// frame. Plain geometry, no engine: the builder turns the plan into bodies, the tests check it.
#pragma once

#include <vector>

#include "sim/geometry/geometry.h"
#include "sim/scene/scene.h"
#include "sim/geometry/shell_outline.h"
#include "sim/geometry/shell_properties.h"

namespace polyroll {

struct PlannedGrain {
    geom::Vec2 position_m;  // in the shell's frame (centre of the polygon at the origin)
    double radius_m = 0.0;
    double mass_kg = 0.0;
};

struct FillPlan {
    geom::Vec2 up;                    // unit vector against gravity, in the shell's frame
    double surface_level_m = 0.0;     // free surface: points with dot(p, up turned by release.pile_tilt_deg) <= level
    double target_mass_kg = 0.0;      // r x inside volume x bulk density
    std::vector<PlannedGrain> grains;
};

// Packs the grains by pouring them (grain_deposition.h) into the inside, in the release pose, up to
// the free surface. The count therefore follows from r and the packing; the masses share the fill's
// target mass in proportion to grain area. Sizes are drawn with run.seed.
FillPlan plan_fill(const Scene& scene, const ShellProperties& shell, geom::Vec2 up_in_shell_frame);

}  // namespace polyroll

namespace polyroll {

// The same fill in grains `scale` times larger in diameter (scale >= 1; InputError otherwise): the
// same fill ratio and bulk density, hence the same fill mass (r x inside volume x bulk density, shared
// among the grains by area) and the same level surface, in about 1/scale^2 as many grains. The
// sandbox uses it to keep real time (app/model_budget.h); the trade study measures what it costs in
// accuracy (the same scaling: src/sweep/tradeoff.cpp).
Scene with_coarser_grains(const Scene& scene, double scale);

}  // namespace polyroll
