// Calibration cost for polyroll bench: see bench_calibration.h.
#include "cli/bench_calibration.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include <fmt/core.h>

#include "sim/model_registry.h"
#include "sim/run_cost.h"
#include "sweep/calibration.h"
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
// With --first-pass-seeds 1, in seed-evaluations (one candidate's runs at one seed): the start at
// both seeds (2), the search's other candidates with new runs at one seed (kEvaluationsWithRuns - 1),
// the best found at its second seed (1).
constexpr int kFirstPassSeedEvaluations = 2 + (kEvaluationsWithRuns - 1) + 1;
// With --first-pass-grains too, the search's runs are all new (the start in coarser grains as well):
// kEvaluationsWithRuns coarser one-seed evaluations, and the start and the final pass at both seeds in
// the scene's grains. kCoarserGrains: the documented command's (docs/calibrate.md).
constexpr double kCoarserGrains = 1.5;
constexpr int kCoarserSeedEvaluations = kEvaluationsWithRuns;
constexpr int kFullSeedEvaluations = 2 * kSeeds;

// The share of `sorted` (ascending) below which `q` of the values lie.
double quantile(const std::vector<double>& sorted, double q) {
    if (sorted.empty()) return 0.0;
    const double at = q * static_cast<double>(sorted.size() - 1);
    const auto lo = static_cast<std::size_t>(at);
    const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
    return sorted[lo] + (at - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

// The cost model's estimate (sim/run_cost.h) against each run's own wall time, given the simulated
// time the run turned out to last: what validate's and calibrate's time left rest on.
struct CostCheck {
    std::vector<double> engine_ratios, other_ratios;  // estimate / measured
    double estimated_s = 0.0, measured_s = 0.0;

    void add(const RunResult& r) {
        const double estimate = run_seconds(r.scene, r.measured.end_time_s);
        if (!(r.wall_time_s > 0.0)) return;
        const bool engine = model_traits(model_that_ran(r)).cost == RunCost::engine_bodies;
        (engine ? engine_ratios : other_ratios).push_back(estimate / r.wall_time_s);
        estimated_s += estimate;
        measured_s += r.wall_time_s;
    }

    void print() {
        for (auto* v : {&engine_ratios, &other_ratios}) std::sort(v->begin(), v->end());
        fmt::print("\nthe cost model (sim/run_cost.h, assets/run-cost.json) against each run's wall time, given the "
                   "simulated time it lasted (estimate / measured):\n");
        auto line = [](const char* what, const std::vector<double>& r) {
            if (r.empty()) return;
            fmt::print("  {:<22} {:>4} runs: median {:.2f}, middle half {:.2f} to {:.2f}, range {:.2f} to {:.2f}\n",
                       what, r.size(), quantile(r, 0.5), quantile(r, 0.25), quantile(r, 0.75), r.front(), r.back());
        };
        line("Box2D runs", engine_ratios);
        line("reduced models", other_ratios);
        std::vector<double> all = engine_ratios;
        all.insert(all.end(), other_ratios.begin(), other_ratios.end());
        std::sort(all.begin(), all.end());
        line("every run", all);
        fmt::print("  summed: {:.1f} s estimated, {:.1f} s measured ({:.2f})\n", estimated_s, measured_s,
                   measured_s > 0 ? estimated_s / measured_s : 0.0);
    }
};

// One seed of every observation's runs, one run at a time on this core: the wall time, and the runs.
struct TimedPlan {
    double wall_s = 0.0;
    std::size_t failed = 0;
};

TimedPlan time_plan(const sweep::ValidationPlan& vp, CostCheck* cost) {
    TimedPlan t;
    const auto start = std::chrono::steady_clock::now();
    for (const sweep::PlannedRun& run : vp.plan.runs) {
        const sweep::RunRecord r = sweep::execute_run(vp.plan, run, {}, false);
        t.failed += r.ok ? 0 : 1;
        if (cost && r.result) cost->add(*r.result);
    }
    t.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return t;
}

std::string failed_text(std::size_t failed) { return failed ? fmt::format(", {} failed", failed) : std::string(); }

}  // namespace

void bench_calibration(const char* fidelity) {
    sweep::CalibrationSetup setup;
    setup.file = sweep::read_observations("");
    setup.overrides = {{"fidelity.preset", fidelity}};
    setup.seeds = kSeeds;
    setup.first_pass_grain_scale = kCoarserGrains;
    const sweep::ValidationPlan vp = sweep::candidate_plan(setup, {}, 1, 1.0);
    CostCheck cost;
    const TimedPlan full = time_plan(vp, &cost);
    const TimedPlan coarser = time_plan(sweep::candidate_plan(setup, {}, 1, kCoarserGrains), nullptr);
    const double wall_s = full.wall_s;
    const double fit_s = wall_s * kSeeds * kEvaluationsWithRuns / kJobs;
    const double first_pass_s = wall_s * kFirstPassSeedEvaluations / kJobs;
    const double coarser_s = (wall_s * kFullSeedEvaluations + coarser.wall_s * kCoarserSeedEvaluations) / kJobs;
    std::size_t early = 0;
    for (const sweep::PlannedRun& run : vp.plan.runs) early += run.point.contains("run.end_at_impact") ? 1 : 0;
    fmt::print("\ncalibration at {}: one evaluation of the bundled observations ({} runs, {} of them ended at the impact "
               "that decides their observation, 1 seed{}) took {:.1f} s on one core, {:.1f} s in grains {:g}x "
               "larger{}\n"
               "  a three-parameter fit (--seeds {}, {} evaluations with new runs, --jobs {} on two idle cores): about "
               "{:.0f} s ({:.1f} min)\n"
               "  the same with --first-pass-seeds 1 ({} one-seed evaluations): about {:.0f} s ({:.1f} min)\n"
               "  the same with --first-pass-seeds 1 --first-pass-grains {:g} ({} one-seed evaluations in the "
               "coarser grains, {} in the scene's): about {:.0f} s ({:.1f} min)\n",
               fidelity, vp.plan.runs.size(), early, failed_text(full.failed), wall_s, coarser.wall_s, kCoarserGrains,
               failed_text(coarser.failed), kSeeds, kEvaluationsWithRuns, kJobs, fit_s, fit_s / 60.0,
               kFirstPassSeedEvaluations, first_pass_s, first_pass_s / 60.0, kCoarserGrains, kCoarserSeedEvaluations,
               kFullSeedEvaluations, coarser_s, coarser_s / 60.0);
    cost.print();
    std::fflush(stdout);
}

}  // namespace polyroll::cli
