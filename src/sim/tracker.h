// The tracker: watches the world after each step and measures what the experiment's video analysis
// measured: the lid centre's position and speed along the ramp, each face impact with the kinetic
// energy just before and after, rest, the behaviour and the terminal velocity, and the energy books.
// It also watches for numerical trouble (non-finite state, speeds at the engine's cap, grains out of
// the shell, energy created) and ends the run as diverged, saying why, rather than record garbage.
#pragma once

#include "sim/measurements.h"
#include "sim/model_run.h"
#include "sim/world_builder.h"

namespace polyroll {

class Tracker {
public:
    explicit Tracker(const SimWorld& world);

    // Carries on the records of a run another model began, handed over at step from.steps: positions
    // and angles from its release, its energy books, its trajectory, impacts and sample times.
    void continue_from(const HandOver& from);

    // Call after each step with the step count since release. Returns false once the run has ended.
    bool observe(long step);

    const Measurements& measurements() const { return m_; }
    Measurements& measurements() { return m_; }
    // The latest state, for displays.
    const TrajectorySample& current() const { return now_; }
    long landed_vertex() const { return landed_vertex_; }
    double start_angle_rad() const { return start_angle_rad_; }

    // Counts grains whose centre lies inside the shell's inner polygon (with a small tolerance).
    int count_grains_inside() const;

private:
    TrajectorySample sample(double time_s) const;
    void finish(Behaviour b, double time_s);
    void diverge(const std::string& why, double time_s);
    void check_impact(double time_s, double kinetic_J);
    bool check_grains(double time_s);

    const SimWorld& w_;
    Measurements m_;
    TrajectorySample now_;
    double upm_ = 100.0;           // engine units per metre
    double energy_scale_J_ = 0.0;  // total mass x g x pivot radius: the scale of the run's energies
    double speed_cap_m_s_ = 0.0;
    double contact_tol_m_ = 0.0;
    long next_sample_step_ = 0;
    long samples_taken_ = 0;
    double step_dt_s_ = 0.0;
    // Faces: the unwrapped index of the highest vertex that has landed (1 = the starting pivot).
    long landed_vertex_ = 1;
    bool impact_pending_ = false;
    double kinetic_before_J_ = 0.0;
    double previous_kinetic_J_ = 0.0;
    double rest_since_s_ = -1.0;
    double start_angle_rad_ = 0.0;
    double potential_at_release_J_ = 0.0;
};

}  // namespace polyroll
