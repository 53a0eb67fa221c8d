// Every default and limit of the sandbox window's own settings, in one place: its sliders' spans,
// the transport's speeds, the real-time cap, the window and the theme. Scene values (polygons,
// materials, ramps) stay in assets/ and the scene fields' limits in sim/scene/scene_fields.cpp; these are
// the window's choices, each with its reason.
#pragma once

#include <array>

#include "sim/scene/window_presets.h"

namespace polyroll::app {

// --- Control ranges. The limits of the scene fields the panel edits are the field table's
// (sim/scene/scene_fields.cpp): the controls clamp to them, so a slider never makes a scene the core refuses.
// These are only the sliders' own spans, for the values a class will use; Ctrl+click types any value
// up to the field's limit.
inline constexpr int kSidesSliderMax = 24;  // 3 to 24 sides on the slider, up to 64 typed
// The experiment ran 5-25 degrees; above about 15 the polygons hop.
inline constexpr double kAngleSliderMaxDeg = 45.0;
inline constexpr int kMaxLanes = kMaxRaceLanes;  // up to four polygons race (sim/scene/window_presets.h)

// --- Transport. Slow motion halves the rate down to 1/16: slow enough to watch one impact.
inline constexpr std::array<int, 5> kSlowMotionDivisors = {1, 2, 4, 8, 16};

// The Step button advances this much simulated time: one frame of real-time playback (a single 1 ms
// tracker step would not show).
inline constexpr double kSingleStepS = 1.0 / 60.0;
// Without vsync (e.g. under Xvfb) the window sleeps to this rate rather than spin a core.
inline constexpr double kFrameRateCapHz = 60.0;

// --- Real time. The physics runs in fixed tracker steps; each window frame takes as many as the
// simulated time owes, but spends at most this much wall time on them, so a slow machine slows the
// simulation down (and the window says so) instead of freezing the UI. The steps run on a second
// thread while the frame is drawn, so the budget may fill most of a 60 frames/s frame (16.7 ms),
// less the panel's own ~2 ms: 14 ms buys the heavy scenes more simulated time than 10 ms for a few
// frames per second (docs/sandbox.md, Speed, has the measurements).
inline constexpr double kPhysicsBudgetPerFrameS = 0.014;
// The physics budget (app/model_budget.h, sim/run_cost.h) measures a scene's seconds per cost unit
// over each this-much wall time of real-time play (a rate window, kRateWindowS) and
// updates the cheaper model the panel offers; the scene stepped never changes with it.
inline constexpr double kBudgetMeasureS = 1.0;
// Only a scene doing at least this many cost units per simulated second (sim/run_cost.h: a lane of G
// grains does (G + 1)^1.46 per engine step at the standard iterations; this is about 200 grains at
// 1,000 steps/s) stands for the next scenes' estimate: a few loose grains cost so little that timer
// noise and the frame's fixed work would decide it, and the power law is fitted from 124 grains up.
inline constexpr double kBudgetMinCostUnitsPerS = 2.3e6;
// "Run to the end" draws no scene, so it may spend most of a frame on physics (the UI still answers).
inline constexpr double kRunToEndBudgetPerFrameS = 0.200;
// A stalled frame (window dragged, machine busy) owes at most this much simulated time.
inline constexpr double kMaxFrameDtS = 0.1;
// The simulated time a --frames capture advances per frame: a fixed 1/60 s, so a capture shows the
// same moment on any machine.
inline constexpr double kCaptureFrameDtS = 1.0 / 60.0;
// The shown real-time ratio averages over about this long.
inline constexpr double kRateWindowS = 1.0;
// The window counts as keeping up while the simulated rate is at least this share of the chosen one.
inline constexpr double kKeepingUpShare = 0.95;

// --- Window and theme.
inline constexpr int kDefaultWidthPx = 1280, kDefaultHeightPx = 800;  // a projector's 1280x800
// The window sizes --size accepts: from a small laptop's to an 8K screen's.
inline constexpr int kMinWidthPx = 640, kMaxWidthPx = 7680, kMinHeightPx = 480, kMaxHeightPx = 4320;
inline constexpr float kBaseFontPx = 18.0f;    // DejaVu Sans at UI scale 1: readable from the back row
inline constexpr float kUiScaleMin = 0.75f, kUiScaleMax = 2.5f, kDefaultUiScale = 1.0f;
inline constexpr float kPanelWidthPx = 400.0f;     // the control panel, at UI scale 1
// The window each unit of UI scale needs: a scale larger than the window allows is shown at the
// largest that fits (800x600 at 1, 1280x800 at 1.48, 1920x1080 at 2), since at 800x600 a
// scale of 2 left the scene a sliver and the panels' text cut.
inline constexpr float kUiScaleWindowWidthPx = 800.0f, kUiScaleWindowHeightPx = 540.0f;
inline constexpr float kPlotsHeightShare = 0.36f;  // the readouts and plots strip, share of the height
// The readout table's widest share of the strip beside the plots: past it its cells wrap. A plot
// narrower than kMinPlotWidthEm (in font heights) beside it is a thumbnail (at UI scale 2 a 60% table
// left the plot one): then the table gets a tab of its own beside the plots instead.
inline constexpr float kReadoutTableMaxShare = 0.6f;
inline constexpr float kMinPlotWidthEm = 16.0f;
// How long a confirmation ("Saved: runs/sandbox/screenshot-001.png") stays over the scene, seconds.
inline constexpr double kFeedbackShowS = 8.0;
inline constexpr double kDefaultColourSpeedMax_m_s = 1.0;  // grain speed at the top of the colour map

// The projector theme's panel background (opaque, a pale blue-grey distinct from the scene's
// off-white) and text: the smoke test looks for this colour where the panel is.
inline constexpr std::array<int, 3> kPanelBackgroundRgb = {226, 232, 242};
inline constexpr std::array<int, 3> kPanelTextRgb = {10, 10, 14};

// Where screenshots and exported runs go unless --out says otherwise.
inline constexpr const char* kDefaultOutDir = "runs/sandbox";

}  // namespace polyroll::app
