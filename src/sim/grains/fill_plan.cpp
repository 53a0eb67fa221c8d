// Grain packing before release: see fill_plan.h.
#include "sim/grains/fill_plan.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "sim/geometry/disc_size.h"
#include "sim/grains/contact_values.h"
#include "sim/errors.h"
#include "sim/grains/grain_deposition.h"
#include "sim/rng.h"
#include "sim/scene/scene_validate.h"

namespace polyroll {

using geom::Vec2;

FillPlan plan_fill(const Scene& scene, const ShellProperties& shell, Vec2 up) {
    FillPlan plan;
    plan.up = up;
    const double r = scene.fill.ratio;
    const MaterialParams& m = scene.fill.material;
    plan.target_mass_kg = r * shell.inside_volume_m3 * m.bulk_density_kg_m3;
    const std::vector<Vec2> inner = shell_inner_polygon_m(scene.shell);
    // The mass is r's; the outline it fills may be taller (the closure's bulk factor) and its top turned
    // from level (release.pile_tilt_deg: counter-clockwise in the shell's frame raises the downhill side).
    const Vec2 surface_up = geom::rotate(up, scene.release.pile_tilt_deg * geom::kPi / 180.0);
    plan.surface_level_m = geom::level_for_area_fraction(inner, surface_up, pile_bulk_share(scene));
    if (r <= 0.0) return plan;

    const double disc_m = disc_diameter_m(scene);
    const double spread = disc_size_spread(scene);
    const double r_max = 0.5 * disc_m * (1.0 + spread);
    Rng rng(scene.run.seed);
    auto next_radius = [&] { return 0.5 * disc_m * (1.0 + spread * rng.uniform(-1.0, 1.0)); };
    // Bounded by the validation's grain limit with room for packings denser than its estimate.
    const size_t max_count = static_cast<size_t>(2.0 * kMaxGrains);
    const std::vector<Disc> discs =
        deposit_grains(inner, surface_up, plan.surface_level_m, next_radius, r_max, max_count, [&] { return rng.uniform(); });
    double area_sum = 0.0;
    for (const Disc& d : discs) {
        plan.grains.push_back({d.centre, d.radius, 0.0});
        area_sum += d.radius * d.radius;
    }
    for (PlannedGrain& g : plan.grains) g.mass_kg = plan.target_mass_kg * g.radius_m * g.radius_m / area_sum;
    return plan;
}

}  // namespace polyroll

namespace polyroll {

Scene with_coarser_grains(const Scene& scene, double scale) {
    if (!(scale >= 1.0) || !std::isfinite(scale))
        throw InputError(fmt::format("coarser grains: scale {:g} is out of range (allowed: 1 or more, finite)", scale));
    Scene s = scene;
    // Discs `scale` times larger stand for scale^2 times as many grains (disc_size.h).
    if (s.fill.material.grains_per_disc)
        *s.fill.material.grains_per_disc *= scale * scale;
    else
        s.fill.material.diameter_m *= scale;
    return s;
}

}  // namespace polyroll
