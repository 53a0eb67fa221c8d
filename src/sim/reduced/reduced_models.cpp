// The reduced models as runs of a scene: see reduced_models.h.
#include "sim/reduced/reduced_models.h"

#include <chrono>

#include "sim/geometry/shell_outline.h"
#include "sim/geometry/shell_properties.h"

namespace polyroll::models {

RollingBody rolling_body(const Scene& scene) {
    const ShellProperties sp = shell_properties(scene.shell);
    RollingBody b;
    b.outer_m = shell_outer_polygon_m(scene.shell);
    b.inner_m = shell_inner_polygon_m(scene.shell);
    b.shell.mass_kg = sp.mass_kg;
    b.shell.inertia_cm_kg_m2 = sp.inertia_kg_m2;  // centre of mass at the polygon's centre
    b.fill_ratio = scene.fill.ratio;
    // Mass per unit cross-section: the bulk fills the inside's depth, so r x area x this is
    // the grain model's fill mass (r x inside volume x bulk density).
    b.fill_areal_density_kg_m2 = scene.fill.material.bulk_density_kg_m3 * scene.shell.depth_m;
    return b;
}

RunResult run_reduced_model(const Scene& scene, FillMotion motion, bool until_invalid) {
    const auto start = std::chrono::steady_clock::now();
    RampFrame track = ramp_frame(scene);
    track.stop_when_invalid = until_invalid;
    const RollingRun run = roll(rolling_body(scene), motion, track);
    RunResult r;
    r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.scene = scene;
    r.shell = shell_properties(scene.shell);
    r.measured = run.measured;
    r.grains = 0;
    r.fill_mass_kg = run.fill_mass_kg;
    r.settle_time_s = 0.0;
    r.settled = true;
    r.steps = run.steps;
    r.model_valid = run.model_valid;
    r.model_invalid_time_s = run.model_invalid_time_s;
    return r;
}

}  // namespace polyroll::models
