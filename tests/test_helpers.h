// Shared helpers for the tests: scenes from the bundled defaults with a few fields changed.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/scene.h"
#include "sim/scene_json.h"
#include "sim/simulation.h"

namespace polyroll::test {

// The default scene with `overrides` (a scene document) on top, resolved and validated.
inline Scene scene_with(const nlohmann::ordered_json& overrides) {
    return resolve_scene({SceneLayer{overrides, "test", {}}});
}

}  // namespace polyroll::test
