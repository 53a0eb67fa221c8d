// A scene moved to a fidelity preset: see fidelity_preset.h.
#include <nlohmann/json.hpp>

#include "sim/scene/fidelity_preset.h"

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

Scene at_finest_box2d(Scene scene) {
    scene.run.model = Model::grains;
    scene.fidelity.preset.clear();
    scene.fidelity.step_hz = 10000.0;
    scene.fidelity.substeps = 8;
    scene.fidelity.velocity_iterations = 40;
    scene.fidelity.position_iterations = 10;
    return scene;
}

}  // namespace polyroll
