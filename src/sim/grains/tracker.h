// The grain simulation's tracker: reads the shell's state and the energy books from the Box2D world
// after each step and measures them by the rules every model shares (shell_tracker.h). What stays
// here is what only the engine needs watching: its speed cap, the grains' own states and whether
// they are still inside the shell.
#pragma once

#include "sim/measurements.h"
#include "sim/model_run.h"
#include "sim/shell_tracker.h"
#include "sim/grains/world_builder.h"

namespace polyroll {

// The rules the grain model's states are measured by: its grain count, energy scale and landing
// tolerance (the engine's gap to the ramp and a rounded vertex's lift), and its divergence wording.
TrackRules box2d_track_rules(const SimWorld& w);

class Tracker {
public:
    explicit Tracker(const SimWorld& world);

    // Carries on the records of a run another model began, handed over at step from.steps: positions
    // and angles from its release, its energy books, its trajectory, impacts and sample times.
    void continue_from(const HandOver& from);

    // Call after each step with the step count since release. Returns false once the run has ended.
    bool observe(long step);

    const Measurements& measurements() const { return rules_.measurements(); }
    Measurements& measurements() { return rules_.measurements(); }
    // The latest state, for displays.
    const TrajectorySample& current() const { return rules_.current(); }
    // The state last read from the world, as the shared rules measured it.
    const ObservedState& observed() const { return observed_; }
    long landed_vertex() const { return rules_.landed_vertex(); }
    double start_angle_rad() const { return rules_.release().angle_rad; }

    // Counts grains whose centre lies inside the shell's inner polygon (with a small tolerance).
    int count_grains_inside() const;

private:
    ObservedState observe_world(double time_s) const;
    GrainCheck check_grains() const;

    const SimWorld& w_;
    double upm_ = 100.0;  // engine units per metre
    double speed_cap_m_s_ = 0.0;
    double step_dt_s_ = 0.0;
    double potential_at_release_J_ = 0.0;
    ObservedState observed_;
    ShellTracker rules_;
};

}  // namespace polyroll
