// A run of `--model auto`: the model choose_model picks for the scene. For an empty shell, the rigid
// impact model until the tracker step before it stops holding (docs/physics.md: the normal force it
// needs turns negative, or the friction it needs exceeds the ramp's); from there the same rigid body
// free to leave the ramp and to slide on it
// (sim/reduced/free_body_run.h: flights, vertex impacts, rolling and sliding), which hands the shell to
// Box2D only where it meets a contact it does not model. Each stage is started by the registry
// (model_registry.h) and the records carry on across each hand-over (HandOver); no Box2D world is
// built unless the last one happens, which is where auto's speed comes from.
#pragma once

#include <memory>

#include "sim/model_choice.h"
#include "sim/model_run.h"

namespace polyroll {

class AutoRun final : public ModelRun {
public:
    explicit AutoRun(const Scene& scene);  // scene.run.model == automatic, validated

    bool step() override;
    bool finished() const override { return run_->finished(); }
    long steps() const override { return run_->steps(); }
    const Scene& scene() const override { return scene_; }
    RunSnapshot snapshot() const override { return run_->snapshot(); }
    ShellNow shell_now() const override { return run_->shell_now(); }
    const Measurements& measured() const override { return run_->measured(); }
    // The running model's result, with the scene as given (model auto) and the choice.
    RunResult result() const override;
    int grains() const override { return run_->grains(); }
    HandOver hand_over() const override { return run_->hand_over(); }
    void run_to_end() override;

    // hand_over_time_s is set once the hand-over has happened.
    const ModelChoice& choice() const { return choice_; }
    const ModelChoice* model_choice() const override { return &choice_; }

private:
    void hand_over_if_due();

    Scene scene_;
    ModelChoice choice_;
    enum class Stage { first, flight, then };
    Stage stage_ = Stage::first;
    std::unique_ptr<ModelRun> run_;
    long lift_off_step_ = -1;   // the tracker step at which the rigid model hands over; -1: never
    long hand_over_step_ = -1;  // the tracker step at which the free rigid body hands over; -1: never
};

}  // namespace polyroll
