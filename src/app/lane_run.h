// One lane's run, stepped by the window: the grain simulation itself, or, for the reduced models
// (which compute a whole run in under a millisecond), a playback of their result in the same fixed
// steps. Either way the lane gives a snapshot to draw, the measurements so far (what the readouts
// and plots show) and the RunResult to export.
#pragma once

#include <memory>

#include "render/snapshot.h"
#include "sim/measurements.h"
#include "sim/scene.h"
#include "sim/simulation.h"

namespace polyroll::app {

class LaneRun {
public:
    virtual ~LaneRun() = default;
    virtual bool step() = 0;  // one tracker step; false once the run has ended
    virtual bool finished() const = 0;
    virtual double time_s() const = 0;
    double step_s() const { return 1.0 / scene().fidelity.step_hz; }
    virtual const Scene& scene() const = 0;
    virtual render::Snapshot snapshot() const = 0;
    // What has been measured up to now (the behaviour stays "running" until the run has ended).
    virtual const Measurements& measured() const = 0;
    // The files `polyroll run` would write for this run, as far as it has gone.
    virtual RunResult result() const = 0;
    virtual int grains() const = 0;
};

// Builds (and, for grains, settles) a validated scene: may take seconds for thousands of grains,
// so the window calls it on a worker thread.
std::unique_ptr<LaneRun> make_lane_run(const Scene& scene);

// The shell's pose of a rigid polygon rolling without slipping: the lid centre `position_m` down the
// ramp from its release point and turned by `angle_deg` (positive rolling down) since release, its
// lowest vertex on the surface. For the reduced models, which record only these two numbers.
struct ShellPose {
    geom::Vec2 centre_m;
    double angle_rad = 0.0;
};
ShellPose rolling_pose(const Scene& scene, double position_m, double angle_deg);

}  // namespace polyroll::app
