// Stepping the grain engine in a frame that moves down the track with the pile (a Galilean change
// of frame), so that Box2D's broad phase sees the grains' motion relative to one another rather
// than the pile's whole speed.
//
// Why: Box2D 2.4.1 fattens each fixture's box by a margin and by four steps of its own travel
// (b2_aabbMultiplier), and keeps a contact for every pair of fattened boxes that overlap, touching
// or not. A pile rolling at 0.8 m/s keeps about 18 contacts a disc in the ramp's frame, of which
// fewer than 2 touch; in the pile's frame its travel per step is its relative motion, the boxes
// shrink and so does the contact list every step walks (docs/engine-cost.md).
//
// How, for each engine step: U, the grains' mean velocity along the track, is taken from every
// dynamic body and given to the ramp (kinematic in this frame) as -U; Box2D steps; U is given back
// to every dynamic body, and b2World::ShiftOrigin moves every body and broad-phase box by U dt, which
// puts the ramp back exactly where it was. Newton's laws, the contacts (relative velocities and
// positions) and gravity are the same in both frames, so the step is the same in exact arithmetic;
// in floats it differs by rounding. Positions, velocities and everything the tracker reads stay in
// the ramp's frame between steps.
#pragma once

#include <box2d/box2d.h>

namespace polyroll {

struct SimWorld;

// The frame's velocity for the next engine step, in engine units along the track: the grains' mean,
// or 0 where the frame is off (fidelity.frame = ramp), there are no grains, the shell is held or
// asleep, or the pile is all but still.
float frame_velocity_units(const SimWorld& w);

// One engine step of `dt` seconds with every body seen from a frame moving at `u` units/s along the
// track (0: the ramp's own frame, a plain b2World::Step).
void step_in_frame(SimWorld& w, float dt, float u);

}  // namespace polyroll
