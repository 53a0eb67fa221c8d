// The per-step hook for applied forces: called before every engine step (fidelity.substeps per
// tracker step, settling included) with the engine step in seconds, where forces the contacts do not
// give (for example grain friction on the lids) are applied to the world's bodies. Box2D-free to name.
#pragma once

#include <functional>

namespace polyroll {

struct SimWorld;
using ForceHook = std::function<void(SimWorld& world, double engine_step_s)>;

}  // namespace polyroll
