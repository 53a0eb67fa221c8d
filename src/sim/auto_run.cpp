// `--model auto`: the rule and the run that follows it; see model_choice.h and auto_run.h.
#include "sim/auto_run.h"

#include <cmath>

#include "sim/model_registry.h"
#include "sim/models/reduced_run.h"

namespace polyroll {

ModelChoice choose_model(const Scene& scene) {
    ModelChoice c;
    if (scene.fill.ratio == 0.0) {
        c.model = Model::rigid;
        c.then = Model::grains;
        c.reason =
            "empty shell: the rigid impact model is the exact limit of an empty shell while it stays on the ramp "
            "(docs/physics.md); Box2D takes the shell over at the step before the normal force the model needs "
            "would turn negative (lift-off)";
    } else {
        // docs/tradeoff/tradeoff.md, over its 21 scenes against the reference.
        c.model = Model::grains;
        c.reason =
            "filled shell: the reduced models do not represent a fill well enough (trade study: terminal velocity "
            "error 27% for rigid and 34% for segments, wrong behaviour in 14% and 0% of scenes, against 5.0% and "
            "0% for grains at the standard preset)";
    }
    return c;
}

AutoRun::AutoRun(const Scene& scene) : scene_(scene), choice_(choose_model(scene)) {
    Scene first = scene;
    first.run.model = choice_.model;
    if (choice_.model == Model::rigid && choice_.then) {
        // The rigid model computes its whole run at once, so the lift-off time is known from the start.
        auto rigid = std::make_unique<models::ReducedRun>(first, models::FillMotion::frozen);
        const RunResult whole = rigid->result();
        if (whole.model_invalid_time_s)
            hand_over_step_ = static_cast<long>(std::floor(*whole.model_invalid_time_s * scene.fidelity.step_hz));
        run_ = std::move(rigid);
    } else {
        run_ = start_run(first);
    }
    hand_over_if_due();
}

void AutoRun::hand_over_if_due() {
    if (hand_over_step_ < 0 || choice_.hand_over_time_s || run_->steps() < hand_over_step_ || run_->finished())
        return;
    Scene next = scene_;
    next.run.model = *choice_.then;
    run_ = continue_run(next, run_->hand_over());
    choice_.hand_over_time_s = run_->time_s();
}

bool AutoRun::step() {
    if (run_->finished()) return false;
    run_->step();
    hand_over_if_due();
    return !run_->finished();
}

void AutoRun::run_to_end() {
    if (hand_over_step_ >= 0 && !choice_.hand_over_time_s) {
        while (run_->steps() < hand_over_step_ && run_->step()) {
        }
        hand_over_if_due();
    }
    run_->run_to_end();
}

RunResult AutoRun::result() const {
    RunResult r = run_->result();
    r.scene.run.model = Model::automatic;
    r.model_choice = choice_;
    return r;
}

}  // namespace polyroll
