// Scoring a validation plan's runs from the results tables of a sweep folder: the rows each
// observation's runs became, turned into ScoredRuns and scored (validate and calibrate share this).
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <vector>

#include "sweep/observations.h"
#include "sweep/scorecard.h"

namespace polyroll::sweep {

// Every finished row of every table in `dir` (results.csv, shards/*.csv) whose index and run id are
// the plan's, by plan index. A run that no table holds has no entry.
std::map<std::size_t, ScoredRun> finished_outcomes(const SweepPlan& plan, const std::filesystem::path& dir);

// Each observation scored from its runs. `table_index[i]` is the index under which vp.plan's run i is
// recorded in `outcomes` (empty: the same index). A run with no outcome counts as failed.
std::vector<ObservationScore> score_validation(const ObservationFile& file, const ValidationPlan& vp,
                                               const std::map<std::size_t, ScoredRun>& outcomes,
                                               const std::vector<std::size_t>& table_index = {});

}  // namespace polyroll::sweep
