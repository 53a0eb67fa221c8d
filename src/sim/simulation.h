// One run of a scene: the world, its tracker and the clock, stepped one tracker step at a time.
// The CLI runs it to the end; a window or renderer can step it and read the state between steps.
#pragma once

#include <memory>
#include <optional>

#include "sim/measurements.h"
#include "sim/scene.h"
#include "sim/tracker.h"
#include "sim/world_builder.h"

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
    double balance_correction_deg = 0.0;  // see balance_on_pivot in world_builder.cpp
    long steps = 0;
    double wall_time_s = 0.0;  // building, settling and running, measured by the caller's clock
    // The reduced models assume the polygon stays on the ramp; false once the normal force they need
    // turns negative (the real polygon hops), from model_invalid_time_s on. Always true for grains.
    bool model_valid = true;
    std::optional<double> model_invalid_time_s;
};

class Simulation {
public:
    explicit Simulation(const Scene& scene);  // builds and settles; the scene must be validated
    bool step();                              // one tracker step; false once the run has ended
    bool finished() const;
    double time_s() const { return static_cast<double>(steps_) / world_->scene.fidelity.step_hz; }
    long steps() const { return steps_; }

    const SimWorld& world() const { return *world_; }
    const Tracker& tracker() const { return *tracker_; }
    RunResult result() const;  // wall_time_s left 0

private:
    std::unique_ptr<SimWorld> world_;
    std::unique_ptr<Tracker> tracker_;
    long steps_ = 0;
};

// Runs a validated scene to its end and times it.
RunResult run_scene(const Scene& scene);

}  // namespace polyroll
