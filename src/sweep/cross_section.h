// What the 2D cross-section costs in accuracy: the grain model (2D, at the standard preset) without a
// closure, the same with the bundled pile-bulk closure, and the 3D reference (--model dem3d, Yade) on the small hexagon and
// octagon a quarter, three eighths and half full of BBs, at angles around each scene's thresholds, two
// seeds each. Per scene: each column's behaviour and distance at every angle, the first-impact and
// sustained-rolling thresholds, the energy kept at the first impact (read kKineticDelay_s after the
// landing in all three), the terminal velocity and the cost, and each 2D column's gaps to 3D. Runs
// through the sweep engine, so it resumes and shards like any sweep.
#pragma once

#include <string>

#include "sweep/results_table.h"
#include "sweep/sweep_plan.h"

namespace polyroll::sweep {

SweepPlan cross_section_plan();

struct CrossSectionReport {
    std::string markdown;  // cross-section.md
    // One row per run: scene, model (its column: grains, grains+pile-bulk or dem3d), angle, seed,
    // behaviour, distance (the figure's data).
    std::string maps_csv;
};

// `dir`: the sweep folder, whose runs/<id>/impacts.csv give each run's first impact.
CrossSectionReport analyse_cross_section(const SweepPlan& plan, const TableFile& table,
                                         const std::filesystem::path& dir);

}  // namespace polyroll::sweep
