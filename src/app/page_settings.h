// The web page's scene from its address (?preset=race, ?sides=8&fill=0.375&material=rice&angle=14),
// so a teacher can put a link to one demonstration on the board, and polyroll-sandbox's flags of the
// same names (--sides 8). Both take every scene field that has a command-line flag and a panel control,
// by the flag's name (window_scene_fields): a field's row in sim/scene/scene_fields.cpp is its key here,
// its limits and its words, as on the command line and in Python. Typed text is read by the core
// (sim/scene/field_text.h) and values are checked by resolving the scene, so the page and the window
// refuse sides=2 in the command line's words. Parsing is plain C++ (tested natively in polyroll_tests);
// the page hands its query string to parse_page_query.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/sandbox_state.h"
#include "sim/scene/scene_fields.h"
#include "sim/scene/scene_json.h"

namespace polyroll::app {

// The scene fields the window's flags and the page's address take: every field with a command-line
// flag and a panel control, in the scene table's order, named by field_key ("--sides" -> "sides").
const std::vector<const SceneField*>& window_scene_fields();

struct PageSettings {
    std::optional<std::string> preset;  // a sandbox preset (assets/sandbox-presets.json)
    // The scene fields given (the selected lane's or, for a shared control, every lane's), as a scene
    // layer whose labels say how each was given ("sides=8" on the page, "--sides" as a flag).
    SceneLayer scene{nlohmann::ordered_json::object(), "", {}};
    std::optional<long> frames;  // play this many frames, then stop and report (the page's test)
    bool paused = false;         // start paused
    bool bench = false;          // time the frames, as polyroll-sandbox --bench (default preset hexagon-large-rice)

    // The value given for the field at `path`, or nullptr.
    const nlohmann::ordered_json* field(std::string_view path) const;
};

// The keys the query accepts, for messages: "preset, polygon, sides, ..., frames, paused, bench".
std::string page_query_keys();

// Parses "a=1&b=2" (with or without the leading '?', percent-encoding and '+' decoded). Throws
// InputError naming every bad setting: an unknown key, a value not of the field's type ("sides=six:
// not a whole number (allowed: 3 to 64)"), a value the scene refuses, in the command line's words
// ("shell.sides = 2 (from sides=2) is out of range (allowed: 3 to 64)"), an unknown preset.
PageSettings parse_page_query(std::string_view query);

// polyroll-sandbox's flags of the same names (--preset and window_scene_fields'), given as (key without
// dashes, value) pairs: checked as the command line checks its own ("--sides 6.5: not a whole number
// (allowed: 3 to 64)", "shell.sides = 99 (from --sides) is out of range (allowed: 3 to 64)").
PageSettings parse_window_flags(const std::vector<std::pair<std::string, std::string>>& flags);

// The preset first (replacing the state), then the fields over the selected lane and the shared
// controls. Throws InputError for a combination the scene refuses (too many grains), named as given.
void apply_page_settings(const PageSettings& page, SandboxState& state);

}  // namespace polyroll::app
