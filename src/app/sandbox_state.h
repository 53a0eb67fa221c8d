// What the sandbox's user has chosen, as plain data: the lanes (each a preset document plus its
// controls), the shared controls, the transport and the view. The panel edits it; the loop turns
// it into scenes (scenes_for) when a change is applied. No GLFW or ImGui here.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/controls.h"
#include "app/sandbox_settings.h"
#include "render/frame_layout.h"
#include "sim/scene/scene.h"

namespace polyroll::app {

struct LaneChoice {
    nlohmann::ordered_json base;  // the sandbox preset's scene document for this lane
    LaneControls controls;
};

struct SandboxState {
    std::string preset;                // the sandbox preset last loaded ("" for a scene file)
    std::vector<LaneControls> preset_lanes;  // its lanes' controls as loaded, to tell when they are changed
    SharedControls preset_shared;
    std::string scene_file;            // the scene file loaded (--scene), until a preset replaces it
    std::vector<LaneChoice> lanes;     // 1 to kMaxLanes
    SharedControls shared;
    int selected_lane = 0;             // the lane the main controls edit

    // Changes rebuild the scene and restart at once, or wait for Reset.
    bool restart_on_change = true;
    bool changes_pending = false;      // controls changed since the lanes were built
    // The model stepped: -1 the scenes as asked (however slowly this computer plays them), else the
    // index of the cheaper level (app/model_budget.h) the user picked. Only the user changes it.
    int model_level = -1;

    // The transport as the physics last reported it (PhysicsOutcome), shown by the panel; at the start,
    // what the window asks for (--paused). Play and pause are requests (PhysicsRequests).
    bool playing = true;
    int slow_index = 0;                // into kSlowMotionDivisors
    bool follow = false;
    render::GrainColouring colouring = render::GrainColouring::material;
    float ui_scale = kDefaultUiScale;
    bool high_contrast = true;         // the projector theme
};

// A state showing the named sandbox preset (throws InputError for an unknown name).
SandboxState state_for_preset(const std::string& name);
// A state of one lane from a scene file (polyroll run --scene's format); throws InputError naming the
// file and what is wrong.
SandboxState state_for_scene_file(const std::string& path);
// Loads another preset into an existing state, keeping the transport and view choices.
void load_preset(SandboxState& s, const std::string& name);
// Whether the lanes are still the loaded preset's as it gave them: its button is highlighted only
// then (flags, an address or the panel that change n, r, theta, ... leave no preset highlighted).
bool shows_loaded_preset(const SandboxState& s);

// Every lane's scene from the state; throws InputError for a combination out of range.
std::vector<Scene> scenes_for(const SandboxState& s);

// The UI scale shown in a window of this size: the one asked, or the largest that fits it
// (kUiScaleWindowWidthPx), never below kUiScaleMin.
float fitted_ui_scale(float asked, float width, float height);

// Lane management: a new lane copies the selected one; the last lane cannot be removed.
bool add_lane(SandboxState& s);
bool remove_lane(SandboxState& s, int index);

}  // namespace polyroll::app
