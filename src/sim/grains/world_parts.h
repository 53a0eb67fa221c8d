// The steps build_world takes, one function each: an empty world in the ramp frame, the ramp, the
// shell held in a pose, the grains poured into it and settled, and the shell let go. Internal to
// sim/ (Box2D types); world_builder.h is the way in.
#pragma once

#include <memory>
#include <vector>

#include "sim/grains/world_builder.h"

namespace polyroll::world_parts {

// A point or vector in metres as Box2D's single-precision engine units.
inline b2Vec2 to_b2(geom::Vec2 v_m, const EngineUnits& u) {
    return {static_cast<float>(u.to_units(v_m.x)), static_cast<float>(u.to_units(v_m.y))};
}

// The engine's world with the scene's units, gravity tilted into the ramp frame, the contact
// materials, the shell's polygons and where the run ends; no bodies yet.
std::unique_ptr<SimWorld> empty_world(const Scene& scene, std::vector<ForceHook> hooks);

// A thick static box whose top face is y = 0, reaching past both ends.
void add_ramp(SimWorld& w);

// The radius of the shell's vertex arcs in this engine (vertex_rounding.h): the scene's, or 0 where
// that is no more than the polygons' own skin (b2_polygonRadius), which already rounds them as much.
double engine_vertex_radius_m(const SimWorld& w);

// How far the rounded shell at `angle_rad` sinks below a pose computed for sharp vertices.
double rounding_drop_m(const SimWorld& w, double angle_rad);

// A pose computed for sharp vertices (on its face or its lowest vertex on the surface), sunk by as
// much as the rounded vertex lies above that: the rounded shell touching the ramp.
ShellPose rounded_pose(const SimWorld& w, ShellPose pose);

// The shell, static (held) in `pose` (a rounded_pose), touching the ramp: one trapezoid per side,
// and with rounded vertices their outer corners cut back to the arcs and a circle for each arc.
void add_shell(SimWorld& w, const ShellPose& pose);

// The fill planned in the shell's frame with gravity as seen from `pose`, as dynamic grains.
void pour_grains(SimWorld& w, const ShellPose& pose);

// The hand holds the polygon while the pile comes to rest; then, for the tipped release, shell and
// pile turn together from the face onto the vertex (tip_onto_vertex), and, released on a vertex,
// the whole thing is turned to balance on it (balance_on_pivot in world_fill.cpp).
void settle_grains(SimWorld& w);

// Lets go: the shell becomes dynamic with the real box's mass and inertia, moving
// (its pose is not changed) with the given velocities; the grains wake.
void release_shell(SimWorld& w, geom::Vec2 velocity_m_s, double angular_velocity_rad_s);

}  // namespace polyroll::world_parts
