// The track's shape along its length. The experiment measured only the angle of the track's chord (the
// height and length of the whole 2.54 m track on its supports); a track that sags between its
// supports is steeper near the top and shallower near the bottom. ramp.curvature_deg_per_m describes
// such a track: its local slope falls by that many degrees per metre down the track, about the
// chord's angle ramp.angle_deg at the middle (a circular arc; negative is a hump). 0 is a straight
// track, the value every scene had before the field existed.
//
// The engine keeps its ramp straight and turns gravity instead: a point at distance x down the
// track and height y above it sees gravity at the local slope (the track unrolled; the centripetal
// term v^2 kappa is below 0.2% of g for these tracks and speeds, and left out). Pure math, no engine
// types: the Box2D world, the tracker and the 3D reference's input all read it.
#pragma once

#include "sim/geometry/geometry.h"
#include "sim/scene/scene.h"

namespace polyroll {

// Whether the track is curved at all (a model that assumes a straight ramp cannot run it).
inline bool ramp_is_curved(const RampParams& ramp) { return ramp.curvature_deg_per_m != 0.0; }

// The local slope (degrees from horizontal) at distance x_m down the track from its top.
double local_slope_deg(const RampParams& ramp, double x_m);

// Gravity (m/s^2) in the engine's frame (x down the straight ramp, y along its normal) for a body at
// distance x_m down the track.
geom::Vec2 gravity_at_m_s2(const RampParams& ramp, double gravity_m_s2, double x_m);

// Height (m) of the point x_m down the track and y_m above it, relative to the track's top surface:
// the potential of the gravity above, per unit mass and g.
double height_m(const RampParams& ramp, double x_m, double y_m);

// How far the track's middle lies below its chord (m): curvature x length^2 / 8, the arithmetic
// that turns a support's height into a curvature.
double sag_m(const RampParams& ramp);

// The steepest and shallowest local slopes on the track (at its two ends), degrees.
double top_slope_deg(const RampParams& ramp);
double bottom_slope_deg(const RampParams& ramp);

}  // namespace polyroll
