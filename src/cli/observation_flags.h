// The scene flags of the commands that run an observations file (validate, calibrate): --set
// FIELD=VALUE and every scene flag but the seed, each a single value put on top of every observation.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "flags/command_flags.h"

namespace polyroll::cli {

struct ObservationSceneFlags {
    std::vector<std::string> sets;                                            // FIELD=VALUE
    std::map<std::string, std::pair<std::string, flags::Flag>> scene_text;  // field path -> flag text, its option
};

// Registers --set and the scene flags on `sub` (group "Scene"); `flags` receives their text.
void add_observation_scene_flags(flags::Command& sub, const std::shared_ptr<ObservationSceneFlags>& flags);

// The given flags as field values (InputError for a bad one: one line naming it and what is allowed).
std::vector<std::pair<std::string, nlohmann::ordered_json>> observation_overrides(const ObservationSceneFlags& flags);

// The given flags as command-line words, e.g. {"--fidelity", "draft", "--set", "ramp.friction=0.5"}.
std::vector<std::string> observation_flags_args(const ObservationSceneFlags& flags);

// The given flags as command-line text, e.g. " --fidelity draft --set ramp.friction=0.5".
std::string observation_flags_text(const ObservationSceneFlags& flags);

}  // namespace polyroll::cli
