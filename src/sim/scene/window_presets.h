// The window's presets (assets/sandbox-presets.json): named whole scenes, each a list of one to four
// lanes, every lane a scene document resolved over the defaults like a scene file. The window loads
// them whole (polyroll-sandbox --preset NAME, the page's ?preset=NAME), polyroll render draws a
// preset's lanes side by side (render --preset NAME), and polyroll run and Python's run() take one
// lane (run --preset NAME --lane K, polyroll.run(preset=NAME, lane=K)). GL-free, so every surface
// reads them from here.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/scene/scene.h"
#include "sim/scene/scene_json.h"

namespace polyroll {

// Up to four polygons race side by side: more lanes would be too narrow to read.
inline constexpr int kMaxRaceLanes = 4;

struct WindowPreset {
    std::string name;
    std::string description;
    std::vector<nlohmann::ordered_json> lanes;  // scene documents, 1 to kMaxRaceLanes
};

// In the file's order (the panel's order).
std::vector<std::string> window_preset_names();

// Throws InputError for an unknown name, starting with `label` (the argument as the user wrote it:
// "--preset rcae", "preset='rcae'"; "--preset NAME" when empty) and listing the names; or for a lane
// count out of range.
WindowPreset window_preset(const std::string& name, const std::string& label = "");

// Lane k (1-based) of a preset as a scene layer (its origin "sandbox preset race lane 2"):
// InputError starting with `label` ("--lane 5", "lane=5"; "--lane K" when empty) and naming the
// lanes there are, for a k out of range.
SceneLayer window_preset_lane(const WindowPreset& preset, int k, const std::string& label = "");

// Each lane's document resolved over assets/defaults.json (throws InputError).
std::vector<Scene> resolve_window_preset(const WindowPreset& preset);

}  // namespace polyroll
