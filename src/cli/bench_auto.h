// `polyroll bench --auto`: `--model auto` against `--model grains` on the empty shells it is measured on
// (scenes::auto_shells(), sweep/scene_matrices.h): wall time, speed-up, hand-over and how far apart the
// two runs end, with the rigid model alone and one grain run at the reference preset as yardsticks,
// and what the rigid model's rolling needs (faces that would hop, friction). A benchmark prints;
// tests/test_auto_model.cpp asserts.
#pragma once

#include "sim/scene/scene.h"

namespace polyroll::cli {

// `base`: the scene the empty shells are made from (its fill ratio is set to 0, sides and angle vary).
// Every shell is checked before anything runs: a --tilt that fits the base shell may not fit the
// decagon or the 18-gon, and a table cut off half-way by that is worse than a refusal (InputError
// naming the shell, the tilt and what the shell allows).
void bench_auto(const Scene& base, int repeats);

// The same 16 shells, each run `members` times with its release tilt raised by 0.001 degree a member:
// where a shell hops, one run's terminal velocity is one draw from a spread that tiny changes in the
// state at a landing select (docs/studies/free-body-against-box2d.md), so auto, grains at the scene's fidelity and the finest
// Box2D are compared by their means and ranges. No timings: one run each.
void bench_auto_ensemble(const Scene& base, int members);

}  // namespace polyroll::cli
