// The experimenters' reduced models (docs/physics.md) as runs of a scene: the rigid impact model
// (shell and fill one rigid body, the fill frozen as it lay at release) and the composite segment
// model (the fill re-levels after every impact). Both return the grain simulation's RunResult, with
// the same measurements, so every output and downstream tool works on all three models.
#pragma once

#include "sim/reduced/rolling_polygon.h"
#include "sim/run_result.h"
#include "sim/scene/scene.h"

namespace polyroll::models {

// The scene's shell and fill as a rolling body: the shell's mass and moment of inertia from
// shell_properties(), its outer polygon as outline, the fill's mass r x inside volume x bulk density
// spread uniformly over the inside's cross-section.
RollingBody rolling_body(const Scene& scene);

// Runs a validated scene with the fill moving as `fill` says (frozen: the rigid model; relevel: the
// segment model), and times it. `until_invalid`: stop where the model stops holding (RampFrame::stop_when_invalid).
RunResult run_reduced_model(const Scene& scene, FillMotion fill, bool until_invalid = false);

}  // namespace polyroll::models
