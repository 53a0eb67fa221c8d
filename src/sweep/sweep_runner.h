// Running a sweep's plan on a pool of threads: each run's files go to runs/<id>/ and its row is
// appended to the table as soon as it finishes. A resumed sweep skips every run that any table in
// the folder already holds; a failed run (invalid point, an error, divergence) is a row, not a stop.
#pragma once

#include <atomic>
#include <filesystem>
#include <string>
#include <optional>
#include <utility>
#include <vector>

#include "sweep/results_table.h"
#include "sweep/sweep_plan.h"

namespace polyroll::sweep {

struct SweepOptions {
    std::filesystem::path dir;
    int jobs = 1;
    std::optional<std::pair<int, int>> shard;  // K/N, 1-based
    bool trajectories = false;  // also write each run's trajectory.csv
    bool retry_failed = false;  // run again the runs recorded as failed
    bool quiet = false;         // no progress line
    // By plan index, how long each run is expected to take (calibrate: the same observation run's wall
    // time for the previous candidate): the longest start first, so that no job is left alone with a
    // long run at the end. Runs without an expectation (past the vector, or negative) go last, in plan
    // order. Empty: plan order. Only the order changes: each run's result is its own.
    std::vector<double> expected_s;
};

struct SweepReport {
    std::size_t planned = 0;   // runs in the plan, or in the shard
    std::size_t already = 0;   // found finished in the folder's tables
    std::size_t ran = 0;       // finished in this session
    std::size_t failed = 0;    // of those
    std::string first_failure;  // the reason of this session's failed run first in the plan, if any
    bool interrupted = false;  // stopped early by `stop`; rerunning resumes
    double wall_time_s = 0.0;
    std::filesystem::path table;
};

// This session's table: results.csv, or shards/shard-K-of-N.csv for a shard.
std::filesystem::path table_path(const std::filesystem::path& dir, const std::optional<std::pair<int, int>>& shard);

// Every results table in the folder (results.csv first, then the shards' by name).
std::vector<std::filesystem::path> table_paths(const std::filesystem::path& dir);

// One run: resolves its scene, runs it, writes its files into run_dir (none if empty). Never throws
// for a bad point or a failed run: that is the record's reason.
RunRecord execute_run(const SweepPlan& plan, const PlannedRun& run, const std::filesystem::path& run_dir,
                      bool trajectories);

// Runs what is left of the plan (or of the shard). `stop`, when set, ends the session after the runs
// in flight. A non-shard session ends by merging every table into results.csv.
SweepReport run_sweep(const SweepPlan& plan, const SweepOptions& options, const std::atomic<bool>* stop);

}  // namespace polyroll::sweep
