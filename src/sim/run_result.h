// What a whole run gives back, whatever the model: the scene, the shell's derived properties, the
// measurements, and what only the model that ran has to say (model_blocks). No model's types, so
// results I/O, the sweep table and the sandbox's export can name a result without pulling in a model.
#pragma once

#include <optional>

#include "sim/measurements.h"
#include "sim/model_blocks.h"
#include "sim/model_choice.h"
#include "sim/scene/scene.h"
#include "sim/geometry/shell_properties.h"

namespace polyroll {

struct RunResult {
    Scene scene;
    ShellProperties shell;
    Measurements measured;
    int grains = 0;
    double fill_mass_kg = 0.0;
    double settle_time_s = 0.0;
    bool settled = true;
    double balance_correction_deg = 0.0;  // see balance_on_pivot in world_fill.cpp
    long steps = 0;  // the model's own steps (tracker steps for Box2D, integrator steps for the reduced models)
    double wall_time_s = 0.0;  // building, settling and running, measured by the caller's clock
    // The reduced models assume the polygon stays on the ramp; false once the normal force they need
    // turns negative (the real polygon hops), from model_invalid_time_s on. Always true for grains.
    bool model_valid = true;
    std::optional<double> model_invalid_time_s;
    // What only the model that ran has to say: each a block of summary.json under its key, after
    // "shell". Box2D's "engine" (its length unit, step and speed cap; the reduced models integrate
    // their own equations and have none), the 3D reference's "dem3d_engine" (Yade's version, step, CPU
    // time, threads, the motion in a channel). The model's run fills its block; the core writes the
    // blocks without knowing what they hold (model_blocks.h says why they sit behind a pointer).
    ModelBlocks model_blocks;
    // Set for a run of `--model auto` (scene.run.model == automatic): which model ran, and why.
    std::optional<ModelChoice> model_choice;
};

// The model that computed the end of the run (for auto, the chosen one after any hand-over).
inline Model model_that_ran(const RunResult& r) {
    return r.model_choice ? r.model_choice->last() : r.scene.run.model;
}

}  // namespace polyroll
