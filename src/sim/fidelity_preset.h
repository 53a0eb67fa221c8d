// A scene moved to a named fidelity preset (assets/fidelity.json): the preset's step, sub-steps and
// iterations replace the scene's; everything else stays. Used where one scene is run at several
// fidelities (bench, the sandbox's physics budget).
#pragma once

#include <string>

#include "sim/scene.h"

namespace polyroll {

// Throws InputError for a name that is no fidelity preset.
Scene at_fidelity_preset(Scene scene, const std::string& preset);

}  // namespace polyroll
