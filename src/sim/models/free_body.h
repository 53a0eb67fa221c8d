// An empty shell after lift-off: the rigid polygon as a free body above the ramp (docs/physics.md,
// "After lift-off"). What `--model auto` runs once the rigid impact model's shell would hop, in place
// of Box2D, so a hopping empty shell costs microseconds too.
//
// Three kinds of stretch, with events between them:
// - flight: no contact, exact (a parabola and a constant spin); ends where the lowest vertex meets
//   the ramp;
// - contact on one vertex, sticking (a pendulum about it, pivot_motion.h) or sliding (Coulomb
//   friction, the ramp's coefficient as Box2D mixes it, slide_motion.h), each followed along its
//   Taylor series, exact to rounding; ends where the normal force would turn negative (flight),
//   where sticking needs more friction than the ramp gives (sliding), where the slip stops
//   (sticking), or where a second vertex meets the ramp;
// - impact of one vertex: no bounce (restitution 0, as both ramps), the tangential impulse sticking
//   the vertex if friction allows and sliding it at the friction limit otherwise.
// It stops and says why (`unsupported`) where a scene leaves what it models: two vertices on the
// ramp at once (a face set down flat), a shell coming to rest. The caller hands the shell to Box2D there.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sim/geometry.h"
#include "sim/measurements.h"
#include "sim/shell_pose.h"

namespace polyroll::models {

// A rigid polygon with its centre of mass at its centre (an empty shell).
struct FreeBody {
    std::vector<geom::Vec2> outer_m;  // the outline touching the ramp, as shell_outer_polygon_m
    double mass_kg = 0.0;
    double inertia_kg_m2 = 0.0;  // about the centre
};

// The ramp and the run's rules, in SI units and the ramp frame of shell_pose.h.
struct FreeBodyRules {
    double angle_deg = 0.0;
    double gravity_m_s2 = 0.0;
    double friction = 0.0;  // the shell-ramp Coulomb coefficient (Box2D: sqrt of the two fixtures')
    double end_centre_x_m = 0.0;
    double time_limit_s = 0.0;
    double sample_hz = 0.0;       // trajectory rows
    double sample_grid_hz = 0.0;  // rows at the first multiple of 1 / this at or after j / sample_hz
    double rest_speed_m_s = 0.0;  // slower than this on the ramp: coming to rest (unsupported)
};

// Where the run is taken over: the state now and the records so far.
struct FreeBodyStart {
    double time_s = 0.0;
    ShellState state;
    ShellPose release;               // position and angle are measured from it
    double potential_J = 0.0;        // the potential energy now, relative to release, as booked so far
    long landed_vertex = 1;          // the highest vertex landed, unwrapped (tracker.cpp's numbering)
    Measurements measured;           // the records so far
    // The index of the next trajectory row (row j falls at j / sample_hz on the grid); -1: the number
    // of rows in `measured` (a run sampled at the scene's rate continues its own rows).
    long first_row = -1;
};

struct FreeBodyMotion {
    Measurements measured;            // the records, continued to the end or to `unsupported_time_s`
    std::vector<ShellState> states;   // the state at each trajectory row added (after the start's rows)
    std::vector<long> landed_vertices;  // the highest vertex landed after each row added
    std::optional<double> unsupported_time_s;  // where the run met a contact it does not model
    std::string unsupported_why;
    long flights = 0;                 // stretches without contact
    long slides = 0;                  // contact stretches sliding
    long steps = 0;                   // contact grid points, flight search points and event evaluations
};

// Runs from `start` to the ramp's end, the time limit, or the first contact it does not model.
FreeBodyMotion free_body_motion(const FreeBody& body, const FreeBodyRules& rules, const FreeBodyStart& start);

}  // namespace polyroll::models
