// Sandbox presets (assets/sandbox-presets.json): named whole scenes, each a list of one to four
// lanes, every lane a scene document resolved over the defaults like a scene file.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/scene.h"

namespace polyroll::app {

struct SandboxPreset {
    std::string name;
    std::string description;
    std::vector<nlohmann::ordered_json> lanes;  // scene documents, 1 to kMaxLanes
};

// In the file's order (the panel's order).
std::vector<std::string> sandbox_preset_names();

// Throws InputError naming the choices for an unknown name, or a lane count out of range.
SandboxPreset sandbox_preset(const std::string& name);

// Each lane's document resolved over assets/defaults.json (throws InputError).
std::vector<Scene> resolve_preset(const SandboxPreset& preset);

inline constexpr const char* kDefaultSandboxPreset = "default";

}  // namespace polyroll::app
