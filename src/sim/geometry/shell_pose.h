// Where the shell is and how it moves, in the ramp frame of world_builder.h (x down the slope, y along
// its normal, the surface at y = 0), in SI units. Box2D-free: the reduced models, the snapshots and a
// hand-over between models all speak in these terms.
#pragma once

#include "sim/geometry/geometry.h"
#include "sim/measurements.h"
#include "sim/scene/scene.h"
#include "sim/geometry/shell_properties.h"

namespace polyroll {

// The shell's angle (rad, counter-clockwise; rolling down is clockwise) and the position of its
// centre, in metres.
struct ShellPose {
    double angle_rad = 0.0;
    geom::Vec2 centre_m;
};

// The pose and the velocity of the shell as a rigid body.
struct ShellState {
    ShellPose pose;
    geom::Vec2 velocity_m_s;              // of the centre
    double angular_velocity_rad_s = 0.0;  // counter-clockwise (negative rolling down)
};

// Where the shell is let go: its downhill vertex (of face (0, 1), which spans x = 0 .. side).
inline double release_pivot_x_m(const ShellProperties& shell) { return shell.outer_side_m; }
// The track's local slope there (degrees; the ramp's angle on a straight track): balance is judged
// against it.
double release_slope_deg(const Scene& scene, const ShellProperties& shell);

// Where every model ends a run: the centre this far down the ramp puts the polygon's front at the
// ramp's end.
inline double end_centre_x_m(const Scene& scene, const ShellProperties& shell) {
    return scene.ramp.length_m - shell.outer_circumradius_m;
}

// The release pose: resting on face (0, 1), or on its downhill vertex turned past balance (the
// vertex and tipped releases).
ShellPose release_pose(const Scene& scene, const ShellProperties& shell);
// Where the shell is held while the grains are poured and settle: resting flat on face (0, 1) for
// the tipped release of a shell with a fill, the release pose otherwise.
ShellPose pour_pose(const Scene& scene, const ShellProperties& shell);
// Whether the release stands the shell on its downhill vertex (vertex and tipped).
inline bool released_on_vertex(const ReleaseParams& release) { return release.pose != ReleasePose::face; }

// The pose of a rigid polygon rolling without slipping: the centre `position_m` down the ramp from
// its release point and turned by `angle_deg` (positive rolling down) since release, its lowest
// vertex on the surface. For the reduced models, which record only these two numbers.
ShellPose rolling_pose(const Scene& scene, double position_m, double angle_deg);

// The state of that polygon turning about its lowest vertex with the centre's along-ramp speed of
// `sample` (the pivot is at rest, so the centre's speed fixes the rotation rate).
ShellState rolling_state(const Scene& scene, const TrajectorySample& sample);

}  // namespace polyroll
