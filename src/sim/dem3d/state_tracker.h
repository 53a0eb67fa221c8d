// Measurements from a recorded stream of the shell's states: what the tracker (sim/grains/tracker.h) measures
// from the Box2D world, measured by the same rules from the rows the 3D reference writes (states.csv),
// one per tracker step. Box2D-free, so a saved output can be measured again in the tests.
#pragma once

#include <string>
#include <vector>

#include "sim/measurements.h"
#include "sim/scene/scene.h"
#include "sim/geometry/shell_pose.h"
#include "sim/shell_tracker.h"

namespace polyroll::dem3d {

// One tracker step of a recorded run, in the ramp frame.
struct StateRow {
    double time_s = 0.0;  // since release
    ShellState shell;
    double kinetic_J = 0.0;    // shell and grains
    double potential_J = 0.0;  // shell and grains, relative to release
    geom::Vec2 fill_offset_m;  // the fill's centre of mass from the shell's centre, ramp frame (0, 0 empty)
    int grains_inside = 0;
};

// Reads states.csv (header time_s,x_m,y_m,angle_rad,vx_m_s,vy_m_s,omega_rad_s,kinetic_J,potential_J,
// fill_ahead_m,fill_up_m,grains_inside). Throws std::runtime_error naming the line of a malformed row.
std::vector<StateRow> parse_states_csv(const std::string& text);

// One row as trajectory.csv shows it, measured from the release row; the fill's offset where the box
// holds grains.
TrajectorySample trajectory_sample(const StateRow& r, const StateRow& release, bool has_fill);

// The rules' model-specific part (sim/shell_tracker.h): measure_states sets the divergence messages'
// wording for the box; the caller gives the grains, the energy scale and the contact tolerance (the
// 3D shell meets the ramp with the spheres along its edges, so its vertices stay about their radius
// above the surface).
using polyroll::TrackRules;

// The row as the shared rules observe it; the fill's offset where the box holds grains.
ObservedState observed_state(const StateRow& r, bool has_fill);

// Measures the rows by the rules a Box2D run is measured by (the same ShellTracker): face impacts
// (with the energy before, at the landing, and kKineticDelay_s after), trajectory rows at
// run.sample_hz, rest, the end of the ramp, the time limit, the terminal velocity and the energy
// books; non-finite numbers, grains leaving the box or energy created end it as diverged, saying when
// and why.
Measurements measure_states(const Scene& scene, const std::vector<StateRow>& rows, const TrackRules& rules);

}  // namespace polyroll::dem3d
