// The grain model's run: the Box2D world of a scene (world_builder.h), its tracker and the clock,
// stepped one tracker step at a time. Box2D-free header: the engine stays behind world() and
// tracker(), which only sim/ and the tests look into.
#pragma once

#include <memory>
#include <vector>

#include "sim/grains/force_hook.h"
#include "sim/model_run.h"
#include "sim/run_result.h"
#include "sim/scene/scene.h"

namespace polyroll {

struct SimWorld;
class Tracker;

class Simulation final : public ModelRun {
public:
    // Builds and settles; the scene must be validated. The hooks act before every engine step.
    explicit Simulation(const Scene& scene, std::vector<ForceHook> hooks = {});
    // Carries on a run another model began (see HandOver); the grains, if any, are poured unsettled.
    Simulation(const Scene& scene, const HandOver& from, std::vector<ForceHook> hooks = {});
    ~Simulation() override;

    bool step() override;
    bool finished() const override;
    long steps() const override { return steps_; }
    const Scene& scene() const override;
    RunSnapshot snapshot() const override;
    ShellNow shell_now() const override;
    const Measurements& measured() const override;
    RunResult result() const override;
    int grains() const override;
    HandOver hand_over() const override;

    const SimWorld& world() const { return *world_; }
    const Tracker& tracker() const { return *tracker_; }

private:
    std::unique_ptr<SimWorld> world_;
    std::unique_ptr<Tracker> tracker_;
    long steps_ = 0;
};

}  // namespace polyroll
