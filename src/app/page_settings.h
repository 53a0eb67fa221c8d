// The web page's scene from its address (?preset=race, ?sides=8&fill=0.375&material=rice&angle=14),
// so a teacher can put a link to one demonstration on the board. Parsing is plain C++ (tested
// natively in polyroll_tests); the page hands its query string to parse_page_query.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/sandbox_state.h"

namespace polyroll::app {

struct PageSettings {
    std::optional<std::string> preset;    // a sandbox preset (assets/sandbox-presets.json)
    std::optional<int> sides;             // n of the selected lane (shell.sides)
    std::optional<double> fill_ratio;     // r of the selected lane (fill.ratio)
    std::optional<std::string> material;  // the selected lane's material preset
    std::optional<double> angle_deg;      // theta of the ramp (ramp.angle_deg)
    std::optional<std::uint64_t> seed;    // the grain packing's seed, all lanes (run.seed)
    std::optional<long> frames;           // play this many frames, then stop and report (the page's test)
    bool paused = false;                  // start paused
    bool bench = false;                   // time the frames, as polyroll-sandbox --bench (default preset hexagon-large-rice)
};

// The keys the query accepts, for messages: "preset, sides, fill, material, angle, seed, frames, paused, bench".
std::string page_query_keys();

// Parses "a=1&b=2" (with or without the leading '?', percent-encoding and '+' decoded). Throws
// InputError naming the key, the bad value and what is allowed: an unknown key, a value that is not
// a number, a number out of the field's range (sim/scene/scene_fields), an unknown preset or material.
PageSettings parse_page_query(std::string_view query);

// polyroll-sandbox's flags of the same names (--preset, --sides, --fill, --material, --angle, --seed),
// given as (key without dashes, value) pairs: checked as the address is, each refusal naming the flag
// as the command line has it ("--sides 99: out of range (allowed: 3 to 64)").
PageSettings parse_window_flags(const std::vector<std::pair<std::string, std::string>>& flags);

// The preset first (replacing the state), then the selected lane's and the ramp's controls.
void apply_page_settings(const PageSettings& page, SandboxState& state);

}  // namespace polyroll::app
