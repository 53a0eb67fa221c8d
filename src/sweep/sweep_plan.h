// A sweep's plan: the full, ordered list of runs, each a point (scene fields and their values) over
// a base scene, with a stable id derived from the base and the point. The same command gives the same
// plan; plan.json in the sweep folder holds it, so shards on other hosts run exactly the same runs.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/scene/scene_json.h"

namespace polyroll::sweep {

// One swept scene field and its values, in the order given.
struct SweepAxis {
    std::string field;  // scene JSON path, e.g. "shell.sides" or "fill.material.diameter_m"
    std::string flag;   // how the user named it, for messages: "--sides", "--set shell.depth_m"
    std::vector<nlohmann::ordered_json> values;
};

struct PlannedRun {
    std::size_t index = 0;          // position in the plan: the results table's order
    std::string id;                 // 16 hex digits, a hash of the base scene and the point
    nlohmann::ordered_json point;   // field path -> value, in the plan's field order
};

struct SweepPlan {
    nlohmann::ordered_json base = nlohmann::ordered_json::object();  // a scene document under every point
    std::vector<std::string> fields;  // the swept fields, in column order
    std::vector<std::string> flags;   // fields[i] as the user named it
    std::vector<PlannedRun> runs;
};

// The grid: every combination of the axes' values, the first axis varying slowest. Refuses an axis
// with no values or a value given twice (InputError).
SweepPlan make_grid_plan(const nlohmann::ordered_json& base, const std::vector<SweepAxis>& axes);

// Adds a run with the given point (fields not in plan.fields are refused); sets its index and id.
void add_run(SweepPlan& plan, nlohmann::ordered_json point);

std::string run_id(const nlohmann::ordered_json& base, const nlohmann::ordered_json& point);

// The scene layers of a run: the base, then the point (a field named by its flag in messages).
std::vector<SceneLayer> run_layers(const SweepPlan& plan, const PlannedRun& run);

nlohmann::ordered_json plan_to_json(const SweepPlan& plan);
// Reads a plan written by plan_to_json; throws InputError naming `origin` if it is not one.
SweepPlan plan_from_json(const nlohmann::ordered_json& doc, const std::string& origin);

// plan.json in a sweep folder.
std::filesystem::path plan_path(const std::filesystem::path& dir);
void write_plan(const std::filesystem::path& dir, const SweepPlan& plan);
SweepPlan read_plan(const std::filesystem::path& dir);  // InputError if missing or not a plan

// Shard k of n (1-based): the runs whose index is k - 1 modulo n. Interleaving spreads the costly
// corners of a grid over all shards; the slices are disjoint and together cover the plan.
std::vector<std::size_t> shard_indices(std::size_t run_count, int k, int n);

// Parses "K/N" (1 <= K <= N <= 100000); throws InputError naming the text.
std::pair<int, int> parse_shard(const std::string& text);

// Checks that `field` names a value of the resolved scene (e.g. "ramp.angle_deg"); InputError
// listing the allowed paths otherwise.
void check_scene_field(const std::string& field, const std::string& flag);

}  // namespace polyroll::sweep
