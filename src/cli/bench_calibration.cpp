// Calibration cost for polyroll bench: see bench_calibration.h.
#include "cli/bench_calibration.h"

#include <chrono>
#include <cstdio>

#include <fmt/format.h>

#include "sweep/observations.h"
#include "sweep/sweep_runner.h"

namespace polyroll::cli {

namespace {

// A three-parameter calibration of the bundled observations at the standard preset with the
// defaults (2 seeds, --max-evals 24) asked for 25 evaluations, of which this many had new runs
// (the others were points the optimiser had tried before, found done): docs/calibrate.md.
constexpr int kEvaluationsWithRuns = 23;
constexpr int kSeeds = 2;
constexpr int kJobs = 2;

}  // namespace

void bench_calibration(const char* fidelity) {
    const sweep::ObservationFile file = sweep::read_observations("");
    const sweep::ValidationPlan vp = sweep::make_validation_plan(file, 1, {{"fidelity.preset", fidelity}});
    std::size_t failed = 0;
    const auto start = std::chrono::steady_clock::now();
    for (const sweep::PlannedRun& run : vp.plan.runs) {
        const sweep::RunRecord r = sweep::execute_run(vp.plan, run, {}, false);
        failed += r.ok ? 0 : 1;
    }
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double fit_s = wall_s * kSeeds * kEvaluationsWithRuns / kJobs;
    fmt::print("\ncalibration at {}: one evaluation of the bundled observations ({} runs, 1 seed{}) took {:.1f} s on one "
               "core\n  a three-parameter fit (--seeds {}, {} evaluations with new runs, --jobs {} on two idle cores): "
               "about {:.0f} s ({:.1f} min)\n",
               fidelity, vp.plan.runs.size(), failed ? fmt::format(", {} failed", failed) : std::string(), wall_s, kSeeds,
               kEvaluationsWithRuns, kJobs, fit_s, fit_s / 60.0);
    std::fflush(stdout);
}

}  // namespace polyroll::cli
