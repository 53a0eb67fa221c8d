// A run's files: summary.json (the resolved scene and the results), trajectory.csv, impacts.csv.
// Everything but wall_time_s is a function of the scene, so equal scenes give equal bytes.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "sim/run_result.h"

namespace polyroll {

nlohmann::ordered_json summary_json(const RunResult& r);
std::string trajectory_csv(const RunResult& r);
std::string impacts_csv(const RunResult& r);
double mean_impact_ratio(const Measurements& m);  // 0 without impacts

// Writes the three files into an existing folder, each atomically.
void write_run_files(const std::filesystem::path& dir, const RunResult& r);

}  // namespace polyroll
