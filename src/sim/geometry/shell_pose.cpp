// The shell's pose and state in the ramp frame: see shell_pose.h.
#include "sim/geometry/shell_pose.h"

#include <algorithm>
#include <cmath>

#include "sim/geometry/shell_outline.h"
#include "sim/geometry/ramp_profile.h"

namespace polyroll {

using geom::Vec2;

double release_slope_deg(const Scene& scene, const ShellProperties& shell) {
    return local_slope_deg(scene.ramp, release_pivot_x_m(shell));
}

ShellPose release_pose(const Scene& scene, const ShellProperties& p) {
    const double theta = release_slope_deg(scene, p) * geom::kPi / 180.0;
    const double n = p.sides;
    // Resting on face (0, 1): the face spans x = 0 .. side, vertex 1 (downhill) at x = side.
    const Vec2 pivot = {release_pivot_x_m(p), 0.0};
    const Vec2 centre_from_pivot = {-p.outer_side_m / 2.0, p.outer_apothem_m};
    double rotation = 0.0;  // clockwise, about the pivot
    if (released_on_vertex(scene.release)) {
        // Turn about the downhill vertex until the centre is straight above it (the line from
        // pivot to centre leans pi/n uphill of the ramp normal, the vertical theta), then past it
        // by the tilt. Steeper than pi/n the polygon tips from its face anyway: tilt alone.
        rotation = std::max(0.0, geom::kPi / n - theta) + scene.release.tilt_deg * geom::kPi / 180.0;
    } else {
        rotation = scene.release.tilt_deg * geom::kPi / 180.0;
    }
    ShellPose pose;
    pose.angle_rad = -rotation;
    pose.centre_m = pivot + geom::rotate(centre_from_pivot, -rotation);
    return pose;
}

ShellPose pour_pose(const Scene& scene, const ShellProperties& p) {
    // An empty shell has nothing to pour: it is tipped before the hand lets go, so it starts as held.
    if (scene.release.pose != ReleasePose::tipped || scene.fill.ratio == 0.0) return release_pose(scene, p);
    ShellPose pose;
    pose.centre_m = {release_pivot_x_m(p) - p.outer_side_m / 2.0, p.outer_apothem_m};
    return pose;
}

namespace {
// The outer vertex lowest at this angle, rotated into the ramp frame (relative to the centre).
Vec2 lowest_vertex(const Scene& scene, double angle_rad) {
    Vec2 lowest;
    bool first = true;
    for (const Vec2& v : shell_outer_polygon_m(scene.shell)) {
        const Vec2 r = geom::rotate(v, angle_rad);
        if (first || r.y < lowest.y) lowest = r;
        first = false;
    }
    return lowest;
}
}  // namespace

ShellPose rolling_pose(const Scene& scene, double position_m, double angle_deg) {
    const ShellPose release = release_pose(scene, shell_properties(scene.shell));
    ShellPose p;
    p.angle_rad = release.angle_rad - angle_deg * geom::kPi / 180.0;  // rolling down is clockwise
    p.centre_m = {release.centre_m.x + position_m, -lowest_vertex(scene, p.angle_rad).y};
    return p;
}

ShellState rolling_state(const Scene& scene, const TrajectorySample& sample) {
    ShellState s;
    s.pose = rolling_pose(scene, sample.position_m, sample.angle_deg);
    // The arm from the pivot (the lowest vertex, at rest) to the centre; the centre moves at
    // omega x arm, so its along-ramp speed is omega_cw * arm.y.
    const Vec2 arm = -1.0 * lowest_vertex(scene, s.pose.angle_rad);
    const double omega_cw = arm.y > 0.0 ? sample.speed_m_s / arm.y : 0.0;
    s.velocity_m_s = {omega_cw * arm.y, -omega_cw * arm.x};
    s.angular_velocity_rad_s = -omega_cw;
    return s;
}

}  // namespace polyroll
