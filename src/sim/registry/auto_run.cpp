// `--model auto`'s run: the stages its rule picks, handed on one to the next; see auto_run.h.
#include "sim/registry/auto_run.h"

#include <cmath>

#include "sim/model_registry.h"
#include "sim/model_row.h"
#include "sim/reduced/free_body_run.h"

namespace polyroll {

std::unique_ptr<ModelRun> start_auto_run(const Scene& scene) { return std::make_unique<AutoRun>(scene); }

AutoRun::AutoRun(const Scene& scene) : scene_(scene), choice_(choose_model(scene)) {
    Scene first = scene;
    first.run.model = choice_.model;
    if (choice_.model == Model::rigid && choice_.then) {
        // Computed whole at once up to where it stops holding, so the lift-off time is known from the start.
        run_ = start_run_while_valid(first);
        const RunResult whole = run_->result();
        if (whole.model_invalid_time_s)
            lift_off_step_ = static_cast<long>(std::floor(*whole.model_invalid_time_s * scene.fidelity.step_hz));
    } else {
        run_ = start_run(first);
    }
    hand_over_if_due();
}

void AutoRun::hand_over_if_due() {
    // The rigid run was computed up to lift-off only (it may end there): hand over at that step.
    if (stage_ == Stage::first && lift_off_step_ >= 0 && run_->steps() >= lift_off_step_) {
        // The free rigid body: the rigid model's shell carried on, free to leave the ramp and to slide on it.
        auto flying = std::make_unique<models::FreeBodyRun>(scene_, run_->hand_over());
        choice_.lift_off_time_s = flying->time_s();
        if (flying->hand_over_step()) {
            hand_over_step_ = *flying->hand_over_step();
            choice_.hand_over_why = flying->unsupported_why();
        }
        run_ = std::move(flying);
        stage_ = Stage::flight;
    }
    if (stage_ == Stage::flight && hand_over_step_ >= 0 && run_->steps() >= hand_over_step_) {
        Scene next = scene_;
        next.run.model = *choice_.then;
        run_ = continue_run(next, run_->hand_over());
        choice_.hand_over_time_s = run_->time_s();
        stage_ = Stage::then;
    }
}

bool AutoRun::step() {
    if (run_->finished()) return false;
    run_->step();
    hand_over_if_due();
    return !run_->finished();
}

void AutoRun::run_to_end() {
    if (stage_ == Stage::first && lift_off_step_ >= 0) {
        while (run_->steps() < lift_off_step_ && run_->step()) {
        }
        hand_over_if_due();
    }
    if (stage_ == Stage::flight && hand_over_step_ >= 0) {
        run_->run_to_end();  // to the hand-over step
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
