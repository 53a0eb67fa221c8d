// The auto model's part of polyroll bench: see bench_auto.h.
#include "cli/bench_auto.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "sim/model_registry.h"
#include "sim/scene_names.h"

namespace polyroll::cli {

namespace {

struct Timed {
    RunResult result;
    double best_s = 1e300;
};

Timed time_runs(const Scene& s, int repeats) {
    Timed t;
    for (int rep = 0; rep < repeats; ++rep) {
        t.result = run_scene(s);
        t.best_s = std::min(t.best_s, t.result.wall_time_s);
    }
    return t;
}

}  // namespace

void bench_auto(const Scene& base, int repeats) {
    fmt::print("\nauto against grains on empty shells ({} fidelity for grains), best of {} on one core\n",
               base.fidelity.preset.empty() ? "custom" : base.fidelity.preset, repeats);
    fmt::print("{:>3} {:>5} {:>10} {:>10} {:>8} {:>10} {:>9} {:>9} {:>7}  {}\n", "n", "deg", "auto_s", "grains_s",
               "speedup", "handover", "Vt_auto", "Vt_grains", "Vt_err", "behaviour (auto / grains)");
    double auto_total = 0.0, grains_total = 0.0;
    for (int sides : {6, 8, 10, 18}) {
        for (double angle : {5.0, 10.0, 20.0, 30.0}) {
            Scene s = base;
            s.fill.ratio = 0.0;
            s.shell.sides = sides;
            s.ramp.angle_deg = angle;
            s.run.model = Model::automatic;
            const Timed a = time_runs(s, repeats);
            s.run.model = Model::grains;
            const Timed g = time_runs(s, repeats);
            auto_total += a.best_s;
            grains_total += g.best_s;
            const auto& c = a.result.model_choice;
            const std::string handover = c && c->hand_over_time_s ? fmt::format("{:.3f} s", *c->hand_over_time_s) : "-";
            const auto& va = a.result.measured.terminal_velocity_m_s;
            const auto& vg = g.result.measured.terminal_velocity_m_s;
            const std::string err = va && vg ? fmt::format("{:.1f}%", 100.0 * std::fabs(*va - *vg) / *vg) : "-";
            fmt::print("{:>3} {:>5g} {:>10.5f} {:>10.5f} {:>7.1f}x {:>10} {:>9} {:>9} {:>7}  {} / {}\n", sides, angle,
                       a.best_s, g.best_s, g.best_s / a.best_s, handover,
                       va ? fmt::format("{:.3f}", *va) : "-", vg ? fmt::format("{:.3f}", *vg) : "-", err,
                       to_string(a.result.measured.behaviour), to_string(g.result.measured.behaviour));
            std::fflush(stdout);
        }
    }
    fmt::print("all 16: auto {:.4f} s, grains {:.4f} s, {:.1f}x. handover: when the rigid model handed the shell\n"
               "to Box2D (lift-off); Vt_err: |Vt_auto - Vt_grains| / Vt_grains.\n",
               auto_total, grains_total, grains_total / auto_total);
}

}  // namespace polyroll::cli
