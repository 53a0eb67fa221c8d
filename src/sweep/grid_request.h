// A sweep's grid as a user asks for it, in the command line's vocabulary (lists "a,b,c" and ranges
// "start:stop:step" per scene flag, FIELD=VALUES for any field, seeds as a list or a count), turned
// into a plan and a sweep folder. `polyroll sweep` and the Python module's sweep() both start here,
// so the same request plans the same runs into the same folder with the same messages.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/scene/scene_fields.h"
#include "sweep/sweep_plan.h"

namespace polyroll::sweep {

struct GridRequest {
    nlohmann::ordered_json base = nlohmann::ordered_json::object();  // scene document under every point
    std::string base_origin = "defaults";                             // names it in messages
    std::map<std::string, std::string> axis_text;  // a swept flag ("--angle") -> its values ("5:20:1")
    std::vector<std::string> sets;                 // "FIELD=VALUES"
    std::string seed_list;                         // "1,5,9"
    int seeds = 0;                                 // a count: 1, 2, ..., seeds
    bool large = false;                            // confirms a plan over the bounds below
};

// Plans beyond these are refused unless GridRequest::large confirms them: a mistyped step (--fill
// 0:1:0.001) should cost a line, not a plan.json of hundreds of megabytes or a week of both cores.
inline constexpr double kRunsWithoutLarge = 100000;
inline constexpr double kHoursWithoutLarge = 100;

// The swept scene flags: the fields with a sweep_axis in sim/scene/scene_fields.cpp, in the plan's
// axis order (the last varies fastest; the seed comes last).
std::vector<const SceneField*> axis_fields();

// The plan of the request (InputError for a bad value, a bad base scene or a grid over the bounds).
// `notes` gains what the user should know (numbers given out of order run in ascending order).
SweepPlan make_request_plan(const GridRequest& request, std::vector<std::string>& notes);

// Every point resolved before anything runs: how many no run could use (and the first one's
// reason), and what the valid ones cost at most.
struct GridCheck {
    std::size_t invalid = 0;
    std::string first_invalid;
    double max_cost_s = 0.0;
};
GridCheck check_grid(const SweepPlan& plan);

// Refuses (InputError) a plan with a point no run could use (--fill 25), before anything is written,
// and one estimated over kHoursWithoutLarge with `jobs` runs at a time unless `large`.
void refuse_unrunnable(const SweepPlan& plan, const GridCheck& check, int jobs, bool large);

// The sweep folder for `plan`: a new one (the plan written), the same sweep's (resumed), or the same
// fields with more values (extended, its finished runs kept). Refuses (InputError) a folder holding
// another sweep or something else. `flag` names the folder in messages ("--out").
void open_sweep_folder(const std::filesystem::path& dir, const std::string& flag, SweepPlan& plan,
                       std::vector<std::string>& notes);

}  // namespace polyroll::sweep
