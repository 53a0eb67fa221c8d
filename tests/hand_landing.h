// A hand-made landing for the shell tracker's tests: vertex 2 (the tracker's numbering) of a shell
// pointing straight down, fed as observed states at given heights above the ramp, approach speeds and
// kinetic energies, without any engine. The tracker's impact rules are tested on it exactly.
#pragma once

#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "sim/geometry/shell_outline.h"
#include "sim/geometry/shell_pose.h"
#include "sim/shell_tracker.h"

namespace polyroll::test {

struct LandingRow {
    double height_tol = 0.0;              // the vertex's height above the ramp, in contact tolerances
    double approach_m_s = 0.0;            // its speed towards the ramp
    double kinetic_J = 0.0;
    double angular_velocity_rad_s = 0.0;  // nonzero: turning, so never at rest
};

struct Landing {
    Measurements measured;
    long steps_observed = 0;  // the rows the tracker took before it ended the run (all: the row count)
};

inline Landing measure_landing(const Scene& s, const std::vector<LandingRow>& rows) {
    const double tol_m = 0.0005;
    const int n = s.shell.sides;
    const double angle = -3.0 * geom::kPi / n;  // vertex j points down at pi/n - 2 pi j/n
    const geom::Vec2 arm = geom::rotate(shell_outer_polygon_m(s.shell)[2], angle);
    REQUIRE(std::fabs(arm.x) < 1e-12);
    TrackRules rules;
    rules.energy_scale_J = 1.0;
    rules.contact_tolerance_m = tol_m;
    ShellPose release;
    release.angle_rad = angle;
    ShellTracker tracker(s, release, rules);
    Landing out;
    for (; out.steps_observed < static_cast<long>(rows.size()); ++out.steps_observed) {
        const LandingRow& row = rows[static_cast<size_t>(out.steps_observed)];
        ObservedState o;
        o.time_s = static_cast<double>(out.steps_observed) / s.fidelity.step_hz;
        o.shell.pose.angle_rad = angle;
        o.shell.pose.centre_m = {0.1, row.height_tol * tol_m - arm.y};
        o.shell.velocity_m_s = {0.0, -row.approach_m_s};
        o.shell.angular_velocity_rad_s = row.angular_velocity_rad_s;
        o.kinetic_J = row.kinetic_J;
        o.potential_J = -2.0;
        if (!tracker.observe(out.steps_observed, o)) break;
    }
    out.measured = tracker.measurements();
    return out;
}

}  // namespace polyroll::test
