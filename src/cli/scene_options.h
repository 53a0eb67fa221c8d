// The command-line flags that describe a scene (--sides, --fill, ...), shared by every command that
// runs one. They become the last layer over assets/defaults.json and any --scene file.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "sim/scene.h"

namespace polyroll::cli {

class SceneOptions {
public:
    void add_to(CLI::App& app);
    // Resolves and validates the scene; throws InputError.
    Scene resolve() const;

private:
    struct Flag {
        CLI::Option* option = nullptr;
        std::string field;  // e.g. "shell.sides"
    };
    std::string scene_file_, model_, polygon_, material_, ramp_, fidelity_, release_;
    int sides_ = 0, substeps_ = 0, velocity_iterations_ = 0, position_iterations_ = 0;
    double fill_ = 0, angle_ = 0, tilt_ = 0, step_hz_ = 0, time_limit_ = 0, sample_hz_ = 0;
    std::uint64_t seed_ = 0;
    CLI::Option* scene_option_ = nullptr;
    std::vector<Flag> flags_;
};

}  // namespace polyroll::cli
