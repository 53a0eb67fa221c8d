// What a whole run gives back, whatever the model: the scene, the shell's derived properties, the
// engine units (meaningful for Box2D runs only) and the measurements. Box2D-free, so results I/O,
// the sweep table and the sandbox's export can name a result without pulling in the engine.
#pragma once

#include <optional>
#include <string>

#include "sim/grains/engine_units.h"
#include "sim/measurements.h"
#include "sim/model_choice.h"
#include "sim/scene/scene.h"
#include "sim/geometry/shell_properties.h"

namespace polyroll {

struct RunResult {
    Scene scene;
    ShellProperties shell;
    EngineUnits units;
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
    // Set for a run of the 3D reference (--model dem3d): what Yade ran with and what it cost.
    struct Dem3dEngine {
        std::string yade_version;
        double time_step_s = 0.0;
        double cpu_time_s = 0.0;  // the subprocess's own CPU time (wall_time_s adds starting it)
        int threads = 1;          // Yade's OpenMP threads (dem3d::threads)
        // In a channel (dem3d.channel_width_m): how far the box moved out of its plane, and how often
        // and how hard its ends touched the channel's sides (one reading per tracker step).
        struct ChannelMotion {
            double max_offset_m = 0.0;  // across the track, from where it was released
            double max_yaw_deg = 0.0, max_tilt_deg = 0.0;  // its roll axis turned about the ramp's normal; down the ramp
            long steps = 0, steps_touching = 0;
            double max_side_force_N = 0.0, side_impulse_N_s = 0.0;
        };
        std::optional<ChannelMotion> channel;
    };
    std::optional<Dem3dEngine> dem3d;
    // Set for a run of `--model auto` (scene.run.model == automatic): which model ran, and why.
    std::optional<ModelChoice> model_choice;
};

// The model that computed the end of the run (for auto, the chosen one after any hand-over).
inline Model model_that_ran(const RunResult& r) {
    return r.model_choice ? r.model_choice->last() : r.scene.run.model;
}

}  // namespace polyroll
