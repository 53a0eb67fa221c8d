// Extending a sweep with more values: `polyroll sweep --out DIR` with a grid that holds
// every run of the folder's plan, and more, runs only the new points. A run keeps its id when the
// grid grows (the id is a hash of the base scene and the point, sweep_plan.h), so the runs already
// finished are found by id, re-indexed to the wider plan's order, and kept.
#pragma once

#include <filesystem>
#include <string>

#include "sweep/sweep_plan.h"

namespace polyroll::sweep {

// Why `wider` cannot extend `existing` (another base scene, other swept fields, a run of `existing`
// missing from `wider`), or empty if it can. Equal plans extend trivially.
std::string extension_refusal(const SweepPlan& existing, const SweepPlan& wider);

// Re-indexes the rows of DIR/results.csv to `wider` (by run id; InputError if another sweep holds
// the table's lock, or if the folder has shard tables, which --merge must combine first), then
// replaces the folder's plan with `wider`. Each file is replaced whole, the table first: a crash in
// between leaves rows whose index no longer matches the old plan, which the next run of the same
// command re-indexes again (by id), so nothing finished is lost or counted twice.
void extend_plan(const std::filesystem::path& dir, const SweepPlan& wider);

}  // namespace polyroll::sweep
