// The sandbox's physics side: the lanes, the real-time clock and the transport (playing, running to
// the end), changed only by run(), which the physics worker calls with a frame's requests. The UI
// reads lanes() and clock() only between jobs, while the worker is idle, and learns what a job did
// from its PhysicsOutcome. No GLFW or ImGui here.
#pragma once

#include <functional>

#include "app/lane_set.h"
#include "app/physics_requests.h"
#include "app/sim_clock.h"

namespace polyroll::app {

class SandboxPhysics {
public:
    // `fixed_frames`: a --frames capture, whose every frame advances kCaptureFrameDtS with no wall-time
    // budget, so it shows the same moment on any machine. `now_s` is the wall clock the budgets use.
    SandboxPhysics(bool fixed_frames, std::function<double()> now_s);

    // Applies the requests' commands, then, for a frame's job, takes in finished builds and steps the
    // lanes as far as the clock (or the run to the end) asks within the frame's budget.
    PhysicsOutcome run(const PhysicsRequests& requests);

    const LaneSet& lanes() const { return lanes_; }
    const SimClock& clock() const { return clock_; }

private:
    void apply(const PhysicsRequests& r, PhysicsOutcome& out);
    void step_frame(double wall_dt_s, PhysicsOutcome& out);

    bool fixed_frames_;
    std::function<double()> now_s_;
    LaneSet lanes_;
    SimClock clock_;
    bool playing_ = false;
    bool running_to_end_ = false;
};

}  // namespace polyroll::app
