// One run of a scene: see simulation.h.
#include "sim/simulation.h"

#include <chrono>

#include <fmt/format.h>

#include "sim/errors.h"
#include "sim/models/reduced_models.h"
#include "sim/scene_json.h"

namespace polyroll {

Simulation::Simulation(const Scene& scene) : world_(build_world(scene)) {
    tracker_ = std::make_unique<Tracker>(*world_);
    tracker_->observe(0);  // the release state is the trajectory's first row
}

bool Simulation::finished() const { return tracker_->measurements().behaviour != Behaviour::running; }

bool Simulation::step() {
    if (finished()) return false;
    world_->step();
    ++steps_;
    return tracker_->observe(steps_);
}

RunResult Simulation::result() const {
    RunResult r;
    r.scene = world_->scene;
    r.shell = world_->shell_props;
    r.units = world_->units;
    r.measured = tracker_->measurements();
    r.grains = static_cast<int>(world_->grains.size());
    for (const PlannedGrain& g : world_->fill.grains) r.fill_mass_kg += g.mass_kg;
    r.settle_time_s = world_->settle_time_s;
    r.settled = world_->settled;
    r.balance_correction_deg = world_->balance_correction_deg;
    r.steps = steps_;
    return r;
}

RunResult run_scene(const Scene& scene) {
    if (scene.run.model != Model::grains) return models::run_reduced_model(scene);
    const auto start = std::chrono::steady_clock::now();
    Simulation sim(scene);
    while (sim.step()) {
    }
    RunResult r = sim.result();
    r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace polyroll
