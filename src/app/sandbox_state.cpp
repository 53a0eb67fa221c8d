// The sandbox's choices and the scenes they make: see sandbox_state.h.
#include "app/sandbox_state.h"

#include <algorithm>

#include "app/sandbox_presets.h"
#include "sim/scene/scene_json.h"

namespace polyroll::app {

void load_preset(SandboxState& s, const std::string& name) {
    const SandboxPreset p = sandbox_preset(name);
    const std::vector<Scene> scenes = resolve_preset(p);
    s.preset = name;
    s.scene_file.clear();
    s.lanes.clear();
    for (size_t i = 0; i < scenes.size(); ++i) s.lanes.push_back({p.lanes[i], lane_controls_from(scenes[i])});
    // The ramp, release and physics are shared: the first lane's.
    s.shared = shared_controls_from(scenes.front());
    s.selected_lane = 0;
    s.changes_pending = false;
    s.preset_lanes.clear();
    for (const LaneChoice& lane : s.lanes) s.preset_lanes.push_back(lane.controls);
    s.preset_shared = s.shared;
}

bool shows_loaded_preset(const SandboxState& s) {
    if (s.preset.empty() || s.lanes.size() != s.preset_lanes.size() || !(s.shared == s.preset_shared)) return false;
    for (size_t i = 0; i < s.lanes.size(); ++i)
        if (!(s.lanes[i].controls == s.preset_lanes[i])) return false;
    return true;
}

SandboxState state_for_preset(const std::string& name) {
    SandboxState s;
    load_preset(s, name);
    return s;
}

SandboxState state_for_scene_file(const std::string& path) {
    const SceneLayer layer = read_scene_file(path);
    const Scene scene = resolve_scene({layer});
    SandboxState s;
    s.scene_file = path;
    s.lanes.push_back({layer.doc, lane_controls_from(scene)});
    s.shared = shared_controls_from(scene);
    return s;
}

std::vector<Scene> scenes_for(const SandboxState& s) {
    std::vector<Scene> scenes;
    for (const LaneChoice& lane : s.lanes) scenes.push_back(lane_scene(lane.base, lane.controls, s.shared));
    return scenes;
}

float fitted_ui_scale(float asked, float width, float height) {
    const float fits = std::min(width / kUiScaleWindowWidthPx, height / kUiScaleWindowHeightPx);
    return std::max(kUiScaleMin, std::min(asked, fits));
}

bool add_lane(SandboxState& s) {
    if (static_cast<int>(s.lanes.size()) >= kMaxLanes || s.lanes.empty()) return false;
    const int from = std::clamp(s.selected_lane, 0, static_cast<int>(s.lanes.size()) - 1);
    s.lanes.push_back(s.lanes[from]);
    s.selected_lane = static_cast<int>(s.lanes.size()) - 1;
    return true;
}

bool remove_lane(SandboxState& s, int index) {
    if (s.lanes.size() <= 1 || index < 0 || index >= static_cast<int>(s.lanes.size())) return false;
    s.lanes.erase(s.lanes.begin() + index);
    s.selected_lane = std::clamp(s.selected_lane, 0, static_cast<int>(s.lanes.size()) - 1);
    return true;
}

}  // namespace polyroll::app
