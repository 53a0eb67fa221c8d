// A scene moved to a fidelity preset: see fidelity_preset.h.
#include "sim/fidelity_preset.h"

#include "sim/assets.h"

namespace polyroll {

Scene at_fidelity_preset(Scene scene, const std::string& preset) {
    const auto& v = assets::preset_values(assets::Kind::fidelity, preset);
    scene.fidelity.preset = preset;
    scene.fidelity.step_hz = v.at("step_hz").get<double>();
    scene.fidelity.substeps = v.at("substeps").get<int>();
    scene.fidelity.velocity_iterations = v.at("velocity_iterations").get<int>();
    scene.fidelity.position_iterations = v.at("position_iterations").get<int>();
    return scene;
}

}  // namespace polyroll
