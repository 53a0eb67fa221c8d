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

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sim/geometry/geometry.h"
#include "sim/measurements.h"
#include "sim/reduced/ramp_frame.h"
#include "sim/geometry/shell_pose.h"

namespace polyroll::models {

// A rigid polygon with its centre of mass at its centre (an empty shell).
struct FreeBody {
    std::vector<geom::Vec2> outer_m;  // the outline touching the ramp, as shell_outer_polygon_m
    double mass_kg = 0.0;
    double inertia_kg_m2 = 0.0;  // about the centre
};

// Where the run is taken over: the state now and the records so far.
struct FreeBodyStart {
    double time_s = 0.0;
    ShellState state;
    ShellPose release;               // position and angle are measured from it
    double potential_J = 0.0;        // the potential energy now, relative to release, as booked so far
    long landed_vertex = 1;          // the highest vertex landed, unwrapped (tracker.cpp's numbering)
    Measurements measured;           // the records so far; the run continues their rows
};

// One row of the run, as a run sampled at every tracker step records it.
struct FreeBodyRow {
    ShellState state;
    TrajectorySample sample;
    long landed_vertex = 1;  // the highest vertex landed
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
    // The dense output: the row at tracker step `step` (>= first_step) of a `step_hz` grid, exactly as
    // a run sampled at every step from first_step would record it (held at its last row past it);
    // nullopt where that run would have no row. What drawing and a hand-over need, without a second run.
    std::function<std::optional<FreeBodyRow>(long step, double step_hz, long first_step)> row_at_step;
};

// Runs from `start` to the ramp's end, the time limit, or the first contact it does not model.
FreeBodyMotion free_body_motion(const FreeBody& body, const RampFrame& frame, const FreeBodyStart& start);

}  // namespace polyroll::models
