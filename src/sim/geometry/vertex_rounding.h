// The shell's outer vertices rounded (shell.vertex_radius_m): each corner an arc of that radius,
// tangent to the two faces that meet there, as a printed or sanded box's corner is. The Box2D shell
// carries the arcs as circles and the 3D reference as its edge spheres, both from this one value;
// the reduced models keep the paper's sharp vertices. Plain geometry, no engine types.
#pragma once

#include <cmath>
#include <vector>

#include "sim/geometry/geometry.h"
#include "sim/scene/scene.h"

namespace polyroll {

// How far the arc's centre lies inside the sharp vertex, along the line to the polygon's centre:
// the circle of radius r tangent to both faces (the faces meet at the interior angle pi - 2 pi/n).
inline double vertex_arc_inset_m(int sides, double radius_m) { return radius_m / std::cos(geom::kPi / sides); }

// How far along each face, from the sharp vertex, the arc meets it.
inline double vertex_arc_tangent_m(int sides, double radius_m) { return radius_m * std::tan(geom::kPi / sides); }

// The arcs' centres in the shell's frame, one per outer vertex (the order of shell_outer_polygon_m).
std::vector<geom::Vec2> vertex_arc_centres_m(const ShellParams& shell);

// How far above the ramp (y = 0) the sharp polygon's vertex stands when the rounded shell, at
// `angle_rad`, rests on the arc of the vertex that is lowest: how far the rounded shell sinks below a
// pose computed for sharp vertices (0 on a face). The landing of a rounded vertex is seen this much
// above the surface.
double vertex_rounding_drop_m(const ShellParams& shell, double angle_rad);

// The most a landing vertex can stand above the ramp over every pose: the drop on the vertex itself,
// r (1 / cos(pi/n) - 1).
inline double vertex_rounding_lift_max_m(const ShellParams& shell) {
    return vertex_arc_inset_m(shell.sides, shell.vertex_radius_m) - shell.vertex_radius_m;
}

}  // namespace polyroll
