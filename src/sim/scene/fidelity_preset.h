// A scene moved to a named fidelity preset (assets/fidelity.json), or past them all to the finest
// Box2D polyroll measures against: the step, sub-steps and iterations replace the scene's; everything
// else stays. Used where one scene is run at several fidelities (bench, the sandbox's physics budget).
#pragma once

#include <string>

#include "sim/scene/scene.h"

namespace polyroll {

// Throws InputError for a name that is no fidelity preset.
Scene at_fidelity_preset(Scene scene, const std::string& preset);

// `scene` run by Box2D (the grain model) far finer than any preset: 80,000 engine steps a second
// (10 kHz, 8 sub-steps), 40 velocity and 10 position iterations; an empty shell works in millimetre
// units there (engine_units.h). Where a shell hops, the grain model's answer still moves with the step
// at the reference preset, so this is the nearest to its converged answer polyroll has (bench --auto
// measures against it). Finer is not better: from 320,000 steps a second on, Box2D's single-precision
// positions and angles advance by only a few units in the last place per step
// (docs/studies/free-body-against-box2d.md).
Scene at_finest_box2d(Scene scene);

}  // namespace polyroll
