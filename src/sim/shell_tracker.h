// The measurement rules, once, over a stream of the shell's states: what the experiment's video
// analysis measured (the lid centre's position and speed along the ramp, each face impact with the
// kinetic energy just before and after, rest, the behaviour and the terminal velocity, the energy
// books), and when a run can no longer be trusted (non-finite numbers, energy created, grains out of
// the shell). Box2D-free: the grain simulation (tracker.h) feeds it the states it reads from its world,
// the 3D reference (dem3d/state_tracker.h) the rows it recorded, so both are measured alike.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sim/geometry/geometry.h"
#include "sim/measurements.h"
#include "sim/model_run.h"
#include "sim/scene/scene.h"
#include "sim/geometry/shell_pose.h"

namespace polyroll {

// What a model shows the tracker after a step, in the ramp frame and SI units.
struct ObservedState {
    double time_s = 0.0;  // since release
    ShellState shell;
    double kinetic_J = 0.0;    // shell and grains
    double potential_J = 0.0;  // shell and grains, relative to release
    // The fill's centre of mass from the shell's centre, where the model moves a fill.
    std::optional<geom::Vec2> fill_offset_m;
};

// The grains as the model sees them in its latest state. Asked on the sample clock and when the run
// ends, not every step: counting may be a pass over every grain.
struct GrainCheck {
    int inside = 0;       // grains whose centre lies inside the shell
    std::string trouble;  // why the grains cannot be trusted by the model's own limits; empty if they can
};
using GrainWatch = std::function<GrainCheck()>;

// What differs between the models whose states are measured.
struct TrackRules {
    int grains = 0;               // in the shell at release
    double energy_scale_J = 0.0;  // total mass x g x pivot radius: the scale of the run's energies
    // A landing vertex nearer the ramp than this touches it: each engine keeps its own gap between
    // the shell and the surface.
    double contact_tolerance_m = 0.0;
    // How grains leave this model's shell, and what to try when a run diverges: the divergence
    // messages end with them.
    std::string grains_leave_through = "the shell through its walls";
    std::string remedy = "use a finer fidelity";
};

// The state as trajectory.csv shows it: position and angle measured from the release pose.
TrajectorySample trajectory_sample(const ObservedState& s, const ShellPose& release);

class ShellTracker {
public:
    // `release`: the pose positions and angles are measured from. `grains`: where the model has grains,
    // how it counts them (empty: no fill).
    ShellTracker(const Scene& scene, const ShellPose& release, TrackRules rules, GrainWatch grains = {});

    // Carries on the records of a run another model began, handed over at step from.steps, where the
    // state is `now`: positions and angles from its release, its trajectory, impacts and sample times.
    void continue_from(const HandOver& from, const ObservedState& now);

    // The state after step `step` since release (0: the release itself). Returns false once the run
    // has ended.
    bool observe(long step, const ObservedState& s);

    // Ends the run as diverged at `s` for a reason the model found by its own limits.
    void diverge(const ObservedState& s, const std::string& why);

    // The states ended before any rule ended the run (a recording cut short): the time limit at the
    // last state observed.
    void end_at_last_state();

    bool running() const { return m_.behaviour == Behaviour::running; }
    const Measurements& measurements() const { return m_; }
    Measurements& measurements() { return m_; }
    // The latest state, for displays.
    const TrajectorySample& current() const { return now_; }
    long landed_vertex() const { return landing_.vertex; }
    const ShellPose& release() const { return release_; }

private:
    void check_impact(const ObservedState& s);
    bool check_grains(double time_s, long step);
    void finish(Behaviour b, double time_s);
    void end_diverged(const std::string& why, double time_s, std::optional<int> grains_inside = std::nullopt);

    const Scene& scene_;
    TrackRules rules_;
    GrainWatch grains_;
    std::vector<geom::Vec2> outer_local_m_;
    ShellPose release_;
    double pivot_radius_m_ = 0.0;
    double end_centre_x_m_ = 0.0;
    double step_s_ = 0.0;

    Measurements m_;
    TrajectorySample now_;
    long next_sample_step_ = 0;
    long samples_taken_ = 0;
    // The face-impact detector's state (check_impact).
    struct Landing {
        long vertex = 1;  // the unwrapped index of the highest vertex that has landed (1: the starting pivot)
        bool pending = false;  // a vertex is touching and still approaching: its impact ends in a later step
        double kinetic_before_J = 0.0;    // the pending impact's energy before
        double previous_kinetic_J = 0.0;  // the last step's kinetic energy
    };
    Landing landing_;
    double rest_since_s_ = -1.0;
};

}  // namespace polyroll
