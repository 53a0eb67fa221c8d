// The reduced models in polyroll bench: see bench_models.h.
#include "cli/bench_models.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include <fmt/core.h>

#include "sim/scene/scene_json.h"
#include "sim/model_registry.h"
#include "sim/scene/shell_label.h"

namespace polyroll::cli {

namespace {
// A reduced-model run takes microseconds: repeat it for at least this long, and this many times,
// so the clock's resolution and the first run's cold caches do not dominate.
constexpr double kMinTotalS = 0.2;
constexpr int kMinRuns = 20;

struct Timing {
    double best_s = 1e300;
    double mean_s = 0.0;
    RunResult last;
};

Timing time_model(const Scene& scene, int min_runs, double min_total_s) {
    Timing t;
    double total = 0.0;
    int runs = 0;
    while (runs < min_runs || total < min_total_s) {
        t.last = run_scene(scene);
        t.best_s = std::min(t.best_s, t.last.wall_time_s);
        total += t.last.wall_time_s;
        ++runs;
    }
    t.mean_s = total / runs;
    return t;
}
}  // namespace

void bench_models(const Scene& base, int repeats, std::optional<double> grain_run_s) {
    Scene grains = base;
    grains.run.model = reference_model();
    Timing g;
    if (grain_run_s) {
        g.best_s = g.mean_s = *grain_run_s;
        g.last = run_scene(grains);  // for its behaviour and simulated time only
    } else {
        g = time_model(grains, repeats, 0.0);
    }
    fmt::print("\nreduced models: {}, r = {:g}, at {:g} deg; grains at the {} fidelity; one core\n",
               shell_label(base), base.fill.ratio, base.ramp.angle_deg, base.fidelity.preset);
    fmt::print("{:<9} {:>12} {:>12} {:>8} {:>6} {:>12} {:>12} {:>10} {:>12}  {}\n", "model", "best_run_s", "mean_run_s",
               "sim_s", "faces", "best_face_s", "wall_per_sim", "speed_up", "speed_up_sim", "behaviour");
    auto row = [&](const char* name, const Timing& t) {
        const double sim_s = t.last.measured.end_time_s;
        const double per_sim = sim_s > 0.0 ? t.best_s / sim_s : 0.0;
        const double g_per_sim = g.last.measured.end_time_s > 0.0 ? g.best_s / g.last.measured.end_time_s : 0.0;
        // Faces rolled over: the impacts, at least the one face it started on.
        const size_t faces = std::max<size_t>(1, t.last.measured.impacts.size());
        fmt::print("{:<9} {:>12.3e} {:>12.3e} {:>8.3f} {:>6} {:>12.3e} {:>12.3e} {:>9.0f}x {:>11.0f}x  {}{}\n", name, t.best_s,
                   t.mean_s, sim_s, faces, t.best_s / static_cast<double>(faces), per_sim, g.best_s / t.best_s,
                   per_sim > 0.0 ? g_per_sim / per_sim : 0.0,
                   to_string(t.last.measured.behaviour), t.last.model_valid ? "" : " (model invalid: would hop)");
        std::fflush(stdout);
    };
    row(to_string(grains.run.model).c_str(), g);
    for (Model m : everyday_models()) {
        if (m == grains.run.model) continue;
        Scene s = base;
        s.run.model = m;
        row(to_string(m).c_str(), time_model(s, kMinRuns, kMinTotalS));
    }
    fmt::print("best/mean_run_s: wall time of one whole run (grains: building and settling included);\n"
               "faces: face impacts in the run (at least 1); best_face_s: best_run_s per face;\n"
               "wall_per_sim: wall seconds per simulated second; speed_up: grains' run time over the model's;\n"
               "speed_up_sim: the same per simulated second (the models may stop or reach the end at different times).\n");
}

}  // namespace polyroll::cli
