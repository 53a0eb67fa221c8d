// Saving from the sandbox: numbered file and folder names that never overwrite an earlier save,
// and the current run's files (summary.json, trajectory.csv, impacts.csv, as polyroll run writes
// them), one folder per lane when several race.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sim/run_result.h"

namespace polyroll::app {

// dir/stem-001.ext, dir/stem-002.ext, ...: the first that does not exist (ext "" for a folder).
std::filesystem::path next_numbered(const std::filesystem::path& dir, const std::string& stem, const std::string& ext);

// Writes each lane's files into `folder` (created), or folder/lane-K with several lanes. Returns
// the folders written. Throws std::runtime_error naming the path on failure.
std::vector<std::filesystem::path> export_runs(const std::filesystem::path& folder, const std::vector<RunResult>& runs);

}  // namespace polyroll::app
