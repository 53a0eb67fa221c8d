// The 3D reference in polyroll bench: see bench_dem3d.h.
#include "cli/bench_dem3d.h"

#include <cstdio>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "sim/dem3d/yade_process.h"
#include "sim/errors.h"
#include "sim/model_registry.h"
#include "sim/scene/shell_label.h"

namespace polyroll::cli {

void bench_dem3d(const Scene& base, std::optional<double> grain_run_s) {
    Scene s = base;
    s.run.model = Model::dem3d;
    fmt::print("\n3D reference (dem3d, Yade): {}, r = {:g}, at {:g} deg; contact time {:g} ms, time step {:.3g} us; "
               "one core\n",
               shell_label(base), base.fill.ratio, base.ramp.angle_deg, 1e3 * s.dem3d.contact_time_s,
               1e6 * s.dem3d.contact_time_s * s.dem3d.time_step_share);
    try {
        dem3d::yade_command();
    } catch (const InputError& e) {
        fmt::print("skipped: {}\n", e.what());
        return;
    }
    std::fflush(stdout);
    const RunResult r = run_scene(s);
    const double sim_s = r.measured.end_time_s;
    const double cpu_s = r.model_blocks.json().contains("dem3d_engine") ? r.model_blocks.json().at("dem3d_engine").value("cpu_time_s", 0.0) : 0.0;
    fmt::print("{:>7} {:>8} {:>9} {:>10} {:>14} {:>18} {:>12}  {}\n", "grains", "sim_s", "cpu_s", "wall_s",
               "cpu_per_sim_s", "cpu_ms_per_grain_s", "x_2d_grains", "behaviour");
    const double per_sim = sim_s > 0.0 ? cpu_s / sim_s : 0.0;
    const std::string vs_2d = grain_run_s && *grain_run_s > 0.0 ? fmt::format("{:.1f}", r.wall_time_s / *grain_run_s) : "-";
    fmt::print("{:>7} {:>8.3f} {:>9.1f} {:>10.1f} {:>14.2f} {:>18.3f} {:>12}  {}\n", r.grains, sim_s, cpu_s,
               r.wall_time_s, per_sim, r.grains > 0 ? 1e3 * per_sim / r.grains : 0.0, vs_2d,
               to_string(r.measured.behaviour));
    fmt::print("cpu_s: Yade's own CPU time (pouring, settling and the run); wall_s adds starting it; x_2d_grains: "
               "wall time against the 2D grain run at the scene's fidelity.\n");
}

}  // namespace polyroll::cli
