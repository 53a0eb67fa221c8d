// The sandbox's Dear ImGui panels: the control panel (presets, lanes, n, r, theta, material, ramp,
// release, model, fidelity, advanced friction and restitution, view, save), the readouts and live
// plots (speed against time with face impacts marked, energies), and the status line over the
// scene. They edit the SandboxState and return requests; the loop carries them out.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "app/lane_set.h"
#include "app/model_budget.h"
#include "app/sandbox_state.h"
#include "app/sim_clock.h"
#include "render/colour.h"

struct ImFont;

namespace polyroll::app {

struct UiRequests {
    bool toggle_play = false, step = false, reset = false, run_to_end = false;
    bool screenshot = false, export_run = false, reset_view = false;
    bool controls_changed = false;  // a control changed: rebuild now, or mark pending
    bool model_level_changed = false;  // a cheaper model was picked, or the scene as asked: rebuild at once
    std::optional<std::string> load_preset;
};

// What the panels show besides the state.
struct UiContext {
    const LaneSet* lanes = nullptr;
    const SimClock* clock = nullptr;
    const BudgetChoice* budget = nullptr;        // the model the lanes step (as asked, or the level picked)
    const BudgetChoice* budget_offer = nullptr;  // the cheaper model the budget offers for real time
    bool running_to_end = false;
    bool capture = false;       // --frames: each frame advances a fixed 1/60 s (kCaptureSpeedStatement)
    bool run_over = false;      // every lane ended (or trouble stopped them): Play starts again
    float ui_scale_shown = 1.0f;  // fitted_ui_scale: less than asked in a small window
    std::string control_error;  // the last combination the core refused
    // What the user just did, said over the scene where the eye is ("Saved: ..."), until this time
    // (ImGui's clock).
    std::string feedback;
    double feedback_until_s = 0.0;
    ImFont* large_font = nullptr;
};

// Window-coordinate rectangles of the three regions.
struct UiLayout {
    float panel_w = 0, plots_h = 0, width = 0, height = 0;
};
UiLayout ui_layout(float width, float height, float ui_scale);
// The framebuffer pixels kept between the panels and the scene beside them (left, above, below). A
// window's border is stroked across its edge, half outside it, with a pixel of antialiasing beyond:
// where the scene began at the edge, every frame's panels blended their borders over the scene's
// edge rows, so the scene had to be drawn again there each frame, three more regions of a frame drawn
// where it changed (docs/sandbox.md). Needs the current ImGui style.
float panel_seam_px(float pixel_ratio);


// What the panels laid out this frame, in window coordinates, for the layout checks
// (polyroll-sandbox --layout-report, tests/test_sandbox_smoke.cpp): each window's visible
// rectangle and the extent of its content, and the speed plot's card.
struct LayoutBox {
    std::string name;
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
struct UiLayoutReport {
    std::vector<LayoutBox> windows;   // visible rectangles: "controls", "status", "readouts", "table"
    std::vector<LayoutBox> contents;  // what was laid out in each, same names (may scroll in y only)
    std::vector<LayoutBox> plots;     // "speed", "energy" cards (the one shown)
    float font_px = 0;
};

void draw_control_panel(SandboxState& s, const UiContext& ctx, const UiLayout& L, UiRequests& req,
                        UiLayoutReport* report = nullptr);
void draw_readouts_and_plots(const SandboxState& s, const UiContext& ctx, const UiLayout& L,
                             UiLayoutReport* report = nullptr);
// The status band across the top of the scene (time, state, speed statement, warnings, what the user
// just did, the grain-speed legend), as tall as its wrapped text: the scene starts under it, so it
// never covers the ramps' start, the lanes' badges or their legend. Returns its bottom edge.
float draw_status(const SandboxState& s, const UiContext& ctx, const UiLayout& L, UiLayoutReport* report = nullptr);

// The colour the three panels stand on, which the frame is cleared to (they draw no background of
// their own): the theme's window background, over the scene's background where it is translucent.
render::Rgba panel_background();

// Keyboard shortcuts (when no text field has the keyboard).
void read_shortcuts(SandboxState& s, UiRequests& req);

// The keyboard shortcuts for --help, wrapped into lines of at most `width` characters: "Keys: Space
// play/pause, ...". The same table as read_shortcuts and the panel's labels and tooltips.
std::string shortcut_help(size_t width = 100);

}  // namespace polyroll::app
