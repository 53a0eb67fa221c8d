// The bodies of the reduced models (docs/physics.md): mass properties in the polygon's own frame,
// the fill as triangular segments of uniform density below a level free surface, and the shell and
// segments combined with the parallel-axis theorem. Pure geometry, no engine.
#pragma once

#include <array>
#include <vector>

#include "sim/geometry/geometry.h"

namespace polyroll::models {

// A rigid body in the plane, in the polygon's frame (its centre at the origin).
struct MassProperties {
    double mass_kg = 0.0;
    geom::Vec2 centre_of_mass_m;
    double inertia_cm_kg_m2 = 0.0;  // about the centre of mass, around the roll axis
};

// The two bodies as one: masses add, the centre of mass is mass-weighted, and each moment moves to
// the common centre of mass by the parallel-axis theorem.
MassProperties combine(const MassProperties& a, const MassProperties& b);

// Moment of inertia about `point` (parallel-axis theorem).
double inertia_about(const MassProperties& body, geom::Vec2 point);

// The level h at which the part of a convex polygon with dot(p, up) <= h has area fraction
// `fraction` (0..1) of the whole; `up` is a unit vector. Bisection over the vertex heights brackets
// the level; between two vertex heights the area below is exactly quadratic in h (the chord length
// is linear), so the bracket is solved in closed form: what bisecting to the end would give, without
// its fifty area evaluations per re-levelling.
double fill_level(const std::vector<geom::Vec2>& convex_poly, geom::Vec2 up, double fraction);

// Area of the part of a convex polygon with dot(p, up) <= level, without building that part.
double area_below(const std::vector<geom::Vec2>& convex_poly, geom::Vec2 up, double level);

// The fill of the composite model: the inside below a level free surface holding fraction r of the
// inside area, as triangles of uniform areal density.
struct FillSegments {
    geom::Vec2 up;                                    // against gravity, in the polygon's frame
    double level_m = 0.0;                             // the free surface: dot(p, up) = level
    std::vector<geom::Vec2> region;                   // the clipped inside, counter-clockwise
    std::vector<std::array<geom::Vec2, 3>> triangles; // a fan over `region`
    MassProperties mass;                              // of all triangles together
};

// Clips `inner` (convex, counter-clockwise) at the level holding `fraction` of its area, splits the
// region into triangles and sums their mass properties (docs/physics.md's triangle formulas).
FillSegments fill_segments(const std::vector<geom::Vec2>& inner, geom::Vec2 up, double fraction,
                           double areal_density_kg_m2);

}  // namespace polyroll::models
