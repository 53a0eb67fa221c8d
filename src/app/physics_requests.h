// What crosses between the sandbox's UI thread and its physics worker, and nothing else (MuJoCo's
// pending-requests pattern): the UI fills PhysicsRequests while the physics is idle and hands them
// over with a job; the physics applies them at the start of that job and hands back a
// PhysicsOutcome, which the UI reads after the join. Neither side writes a field of the other.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "sim/scene/scene.h"

namespace polyroll::app {

struct PhysicsRequests {
    // Commands (the panel's buttons and keys), applied first, in the order of these fields.

    // The window found this lane's snapshot not finite: stop every lane with a message.
    std::optional<size_t> non_finite_lane;
    // The model the user picked for the next restart_with: -1 the scenes as asked, else an index into
    // the budget's levels (model_budget.h). The UI sends both together; nothing else changes it.
    std::optional<int> model_level;
    // Throw the lanes away and build these (Reset, a preset, an applied change): back to t = 0, and
    // no longer running to the end.
    std::optional<std::vector<Scene>> restart_with;
    // Wait here until the lanes are built: a capture or a benchmark starts from the built scene.
    bool wait_until_built = false;
    // Play (true) or pause (false); a change restarts the clock at the lanes' time, owing nothing.
    std::optional<bool> play;
    // Advance kSingleStepS of simulated time, and pause.
    bool step = false;
    // Compute the rest of the run without drawing it, kRunToEndBudgetPerFrameS of it per frame.
    bool run_to_end = false;

    // The frame this job advances, if it is a frame's job (a hand-off of commands alone has none):
    // the wall time since the last frame and the slow-motion divisor.
    struct Frame {
        double wall_dt_s = 0.0;
        int slow_divisor = 1;
    };
    std::optional<Frame> frame;

    bool has_commands() const {
        return non_finite_lane || model_level || restart_with || wait_until_built || play || step || run_to_end;
    }
};

struct PhysicsOutcome {
    long steps = 0;              // tracker steps taken in the job, every lane's counted
    double physics_s = 0.0;      // the job's wall time
    double time_s = 0.0;         // the lanes' simulated time after it (the furthest lane's)
    bool playing = false;        // the transport after it: a run to the end pauses when it is over
    bool running_to_end = false;
    bool built = false;          // the lanes finished building in this job (the clock restarted at 0)
    bool build_failed = false;   // a lane could not be built (the message: LaneSet::build_error)
    bool finished = false;       // every lane's run has ended
    bool trouble = false;        // numerical trouble stopped the lanes (the message: LaneSet::trouble)

    bool run_over() const { return finished || trouble; }
};

}  // namespace polyroll::app
