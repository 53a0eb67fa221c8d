// The event-driven core of both reduced models (docs/physics.md): a rigid body with a regular
// polygonal outline rolls without slipping down the ramp, turning about one vertex between face
// impacts (pivot_motion.h); at each impact the angular momentum about the new pivot is conserved.
// The fill either stays frozen as it was at release (the rigid impact model) or re-levels after every
// impact (the composite segment model), the drop of its centre of mass booked as dissipated.
// It measures what the grain tracker measures, in the same ramp frame and conventions.
#pragma once

#include <optional>
#include <vector>

#include "sim/geometry/geometry.h"
#include "sim/measurements.h"
#include "sim/reduced/composite_body.h"
#include "sim/reduced/ramp_frame.h"

namespace polyroll::models {

// What rolls, in the polygon's frame (its centre, the tracked lid centre, at the origin).
struct RollingBody {
    // The outline touching the ramp: a regular polygon laid out like shell_outer_polygon_m (face
    // (0, 1) down at angle 0, vertex 1 downhill of vertex 0).
    std::vector<geom::Vec2> outer_m;
    MassProperties shell;            // everything but the fill
    std::vector<geom::Vec2> inner_m; // the inside the fill occupies (convex, counter-clockwise)
    double fill_ratio = 0.0;         // r: share of the inside area the fill occupies
    double fill_areal_density_kg_m2 = 0.0;  // fill mass per unit area of cross-section
};

enum class FillMotion {
    frozen,   // the fill keeps its shape at release: one rigid body throughout
    relevel,  // after each impact the fill's surface re-levels to horizontal
};

struct RollingRun {
    Measurements measured;
    // The model assumes the polygon stays on the ramp: false once the normal force it needs turns
    // negative (the real polygon would hop), with the first time that happened.
    bool model_valid = true;
    std::optional<double> model_invalid_time_s;
    double min_normal_force_N = 0.0;  // over the whole run
    // Pivots (faces rolled over) on which the normal force the model needs turned negative, counting
    // the first: 1 for a shell that would hop once and then roll, about the number of faces after
    // lift-off for one that would hop at every face (what a hand-back from Box2D could gain).
    long hop_pivots = 0;
    // The friction the model's no-slip assumption needs, as a share of the normal force: the largest
    // |tangential| / normal force the pivot must supply between impacts (where the normal force is
    // positive), and |tangential| / normal impulse at an impact. A ramp with a lower friction
    // coefficient lets the real shell slip there (the grain model's Box2D does).
    double max_friction_share = 0.0;
    double max_impact_friction_share = 0.0;
    double fill_mass_kg = 0.0;
    long steps = 0;                   // integrator steps
    double relevel_dissipated_J = 0.0;  // the part of the dissipated energy from re-levelling
};

// Runs to rest, the ramp's end or the time limit. Throws InputError if the release rotation puts the
// next vertex below the ramp (more than one face past the starting one).
RollingRun roll(const RollingBody& body, FillMotion fill, const RampFrame& track);

}  // namespace polyroll::models
