// A run of `--model auto`: the model choose_model picks for the scene, and for an empty shell the
// rigid impact model handing the shell over to Box2D at the tracker step before it would lift off
// (its validity check, docs/physics.md: the normal force it needs turns negative). The records carry
// on across the hand-over (HandOver, continue_run); a rigid run that never lifts off runs alone,
// which is where auto's speed comes from.
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
    std::unique_ptr<ModelRun> run_;
    long hand_over_step_ = -1;  // the tracker step at which the first model hands over; -1: never
};

}  // namespace polyroll
