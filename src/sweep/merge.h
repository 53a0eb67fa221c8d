// Combining the tables of a sweep folder (results.csv and the shards' shards/*.csv) into results.csv:
// one row per run, sorted by plan index, exactly the table one process would have written (wall
// times aside). A run found in two tables keeps its "ok" row, else the first table's.
#pragma once

#include <filesystem>
#include <vector>

#include "sweep/sweep_plan.h"

namespace polyroll::sweep {

struct MergeReport {
    std::size_t runs = 0;      // in the plan
    std::size_t rows = 0;      // in the merged table
    std::size_t failed = 0;    // rows with status failed
    std::size_t tables = 0;    // tables read
    std::vector<std::size_t> missing;  // plan indices no table holds
};

// Throws InputError if a table is not of this plan (other columns, or a run id that does not match).
MergeReport merge_tables(const SweepPlan& plan, const std::filesystem::path& dir);

}  // namespace polyroll::sweep
