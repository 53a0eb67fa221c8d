// The values one swept parameter takes, from a command-line list: "6,8", "0:1:0.125" (a range with
// an inclusive stop), or both mixed ("0,0.05,0.1:0.9:0.2,1"). Values are JSON: numbers stay numbers
// (whole numbers stay whole, so shell.sides or run.seed accept them), anything else is a string.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace polyroll::sweep {

// Throws InputError naming `name` and the bad item. An empty list is refused.
std::vector<nlohmann::ordered_json> parse_grid_values(const std::string& name, const std::string& text);

// start, start + step, ... up to stop inclusive. Each value is start + i * step (no running sum),
// snapped to 12 significant digits, so 0:1:0.1 ends exactly at 1 and prints 0.3 rather than
// 0.30000000000000004. Throws InputError for step <= 0, stop < start or more than `max_values`.
std::vector<double> inclusive_range(const std::string& name, double start, double stop, double step,
                                    std::size_t max_values = 100000);

// How a value is written in run ids, CSV cells and messages: numbers in their shortest exact form.
std::string value_text(const nlohmann::ordered_json& v);

}  // namespace polyroll::sweep
