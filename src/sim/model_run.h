// One run of a scene, whatever the model computes it: built from the scene (model_registry.h picks
// the model), stepped in the tracker's fixed steps (1 / fidelity.step_hz), and read between steps as
// a snapshot to draw, the measurements so far and the RunResult `polyroll run` writes. A run can
// hand over to another model: hand_over() gives the shell's state and the records so far, and the
// registry's continue_run() builds the next model's run from them, its measurements carrying on.
#pragma once

#include <memory>

#include "sim/measurements.h"
#include "sim/model_choice.h"
#include "sim/run_progress.h"
#include "sim/run_result.h"
#include "sim/run_snapshot.h"
#include "sim/scene/scene.h"
#include "sim/geometry/shell_pose.h"

namespace polyroll {

// What a run hands to the model that continues it, at a tracker step.
struct HandOver {
    long steps = 0;            // tracker steps since release
    ShellState shell;          // now, in the ramp frame
    ShellPose release;         // at release: position and angle are measured from it
    Measurements measured;     // so far (behaviour running): the trajectory and impacts carry on
    long landed_vertex = 1;    // the highest vertex landed, unwrapped (1: the pivot at release)
    double potential_J = 0.0;  // the potential energy now, relative to release, as the run booked it
};

// The hand-over of a run that counts an impact only for a new highest vertex and lands each in turn
// (the reduced models, dem3d): its measurements so far, still running, and the vertex after its last
// impact's as the highest landed.
inline HandOver counted_hand_over(long steps, const ShellState& shell, const ShellPose& release,
                                  const Measurements& shown, double potential_J) {
    HandOver h{.steps = steps, .shell = shell, .release = release, .measured = shown,
               .landed_vertex = 1 + static_cast<long>(shown.impacts.size()), .potential_J = potential_J};
    h.measured.behaviour = Behaviour::running;
    return h;
}

// The shell's state and the tracker's latest sample, without the grains or the speed history: what a
// caller polling every few steps needs (Python's Simulation.shell() and energies()).
struct ShellNow {
    double time_s = 0.0;  // since release
    geom::Vec2 centre_m;  // in the ramp frame
    double angle_rad = 0.0;
    TrajectorySample now;
    int impacts = 0;
};

class ModelRun {
public:
    virtual ~ModelRun() = default;
    virtual bool step() = 0;  // one tracker step; false once the run has ended
    virtual bool finished() const = 0;
    virtual long steps() const = 0;  // tracker steps since release
    double time_s() const { return static_cast<double>(steps()) / scene().fidelity.step_hz; }
    double step_s() const { return 1.0 / scene().fidelity.step_hz; }
    virtual const Scene& scene() const = 0;
    virtual RunSnapshot snapshot() const = 0;
    // A snapshot's shell part alone; a model whose snapshot carries grains says it without them.
    virtual ShellNow shell_now() const {
        const RunSnapshot s = snapshot();
        return {s.time_s, s.shell_centre_m, s.shell_angle_rad, s.now, s.impacts};
    }
    // What has been measured up to now (the behaviour stays "running" until the run has ended).
    virtual const Measurements& measured() const = 0;
    // The files `polyroll run` would write for this run, as far as it has gone (wall_time_s left 0).
    virtual RunResult result() const = 0;
    virtual int grains() const = 0;
    // The state another model continues from (registry: continue_run).
    virtual HandOver hand_over() const = 0;
    // What `--model auto` chose and why (AutoRun); empty for a model the user named.
    virtual const ModelChoice* model_choice() const { return nullptr; }
    // The same run again from its release, without computing it again: for a model that computes its
    // whole run up front at a cost worth saving (the 3D reference) when it is both measured and drawn.
    // Null where running the scene again is the only way (the engine's state cannot be rewound).
    virtual std::unique_ptr<ModelRun> replay() const { return nullptr; }
    // Steps to the end (a model that knows its whole run may jump there). A caller's stop hook
    // (run_progress.h) is asked between steps: it throws RunStopped.
    virtual void run_to_end() {
        while (step()) {
            if (run_stop_requested()) throw RunStopped("the run was stopped before its end");
        }
    }
};

}  // namespace polyroll
