// The live readouts of a lane as text, in SI units: time, position, speed, face impacts, the
// behaviour once known, distance and terminal velocity. Plain strings, so the panel only lays
// them out and the tests read them.
#pragma once

#include <string>
#include <string_view>

#include "app/model_budget.h"
#include "sim/measurements.h"
#include "sim/model_choice.h"
#include "sim/scene/scene.h"

namespace polyroll::app {

struct LaneReadout {
    std::string title;      // "n = 6, r = 0.4 BBs"
    std::string polygon;    // "n = 6"
    std::string fill;       // "empty", "0.4 BBs"
    std::string time;       // "1.23 s"
    std::string position;   // "0.456 m"
    std::string speed;      // "0.12 m/s"
    std::string impacts;    // "7"
    std::string behaviour;  // "rolling", "stopped", ...
    std::string distance;   // "-" until known
    std::string terminal;   // "-" unless it rolled to the end
    std::string model;      // "grains", or what auto chose: "auto: rigid", "auto: rigid, hops from 0.47 s", "auto: grains from 0.41 s"
    std::string model_reason;  // auto's reason (its tooltip); empty for a model the user named
};

// How the panel names a behaviour ("stopped at 1st impact", "rolled to the end", ...).
std::string behaviour_label(Behaviour b);

// `choice`: what `--model auto` chose for the lane (ModelRun::model_choice), null for a named model.
LaneReadout lane_readout(const Scene& scene, const Measurements& m, double time_s,
                         const ModelChoice* choice = nullptr);

// The model row: the model named, or auto's choice as it stands at this moment of the run.
std::string model_label(const Scene& scene, const ModelChoice* choice);

// The model entry of a lane the physics budget made cheaper: "grains 2x larger, draft step" for
// the grain model, "auto: grains 2x larger" for auto's grains, "auto: grains from 0.41 s, grains 2x
// larger" for a lane auto handed to them.
std::string budget_model_label(const Scene& scene, const ModelChoice* choice, const BudgetLevel& level);
// The status line's note of a cheaper model the user picked: "Cheaper model, picked in the panel:
// grains 2x larger".
std::string budget_status(const BudgetLevel& level);

// The status line's one statement of how fast the run plays: the chosen rate
// ("real time", "1/4\u00D7 slow motion (4\u00D7 slower)") while the computer keeps up, else the rate it
// reaches and why ("playing at 0.24\u00D7 real time: this scene costs more than real time here").
// `keeping_up` false only counts while stepping; `ratio` is simulated seconds per wall second.
std::string speed_statement(int slow_divisor, bool stepping, bool keeping_up, double ratio);

// A capture's statement instead (--frames, the page's test): each frame advances a fixed 1/60 s, so
// how fast this computer steps does not show, and no rate is claimed.
inline constexpr const char* kCaptureSpeedStatement = "captured, 1/60 s a frame";

// The status line: the time, the state ("\u25B6 playing", "paused", "run ended: ...") and the speed
// statement, said once: "t = 1.20 s   \u25B6 playing at 0.24\u00D7 real time: ...", never "playing
// playing at".
std::string status_line(double time_s, const std::string& state, const std::string& speed);

// The panel's note for a value typed (Ctrl+click) outside a control's limits, which the control
// clamps: "r (fill) = 50 is outside 0 to 1: set to 1." Empty when inside them.
std::string clamp_note(std::string_view label, double typed, double min, double max);

}  // namespace polyroll::app
