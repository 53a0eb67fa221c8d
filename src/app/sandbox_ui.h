// The sandbox's Dear ImGui panels: the control panel (presets, lanes, n, r, theta, material, ramp,
// release, model, fidelity, advanced friction and restitution, view, save), the readouts and live
// plots (speed against time with face impacts marked, energies), and the status line over the
// scene. They edit the SandboxState and return requests; the loop carries them out.
#pragma once

#include <optional>
#include <string>

#include "app/lane_set.h"
#include "app/model_budget.h"
#include "app/sandbox_state.h"
#include "app/sim_clock.h"

struct ImFont;

namespace polyroll::app {

struct UiRequests {
    bool toggle_play = false, step = false, reset = false, run_to_end = false;
    bool screenshot = false, export_run = false, reset_view = false;
    bool controls_changed = false;  // a control changed: rebuild now, or mark pending
    bool full_detail_changed = false;  // the full-detail box was clicked: rebuild at once
    std::optional<std::string> load_preset;
};

// What the panels show besides the state.
struct UiContext {
    const LaneSet* lanes = nullptr;
    const SimClock* clock = nullptr;
    const BudgetChoice* budget = nullptr;  // what the physics budget chose for the lanes
    bool running_to_end = false;
    std::string control_error;  // the last combination the core refused
    std::string last_saved;     // where the last screenshot or export went
    ImFont* large_font = nullptr;
};

// Window-coordinate rectangles of the three regions.
struct UiLayout {
    float panel_w = 0, plots_h = 0, width = 0, height = 0;
};
UiLayout ui_layout(float width, float height, float ui_scale);

void draw_control_panel(SandboxState& s, const UiContext& ctx, const UiLayout& L, UiRequests& req);
void draw_readouts_and_plots(const SandboxState& s, const UiContext& ctx, const UiLayout& L);
void draw_status(const SandboxState& s, const UiContext& ctx, const UiLayout& L);

// Keyboard shortcuts (when no text field has the keyboard).
void read_shortcuts(SandboxState& s, UiRequests& req);

}  // namespace polyroll::app
