// `--model auto`: the rule and the run that follows it; see model_choice.h and auto_run.h.
#include "sim/auto_run.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/model_registry.h"
#include "sim/reduced/free_body_run.h"
#include "sim/scene/scene_names.h"

namespace polyroll {

bool fill_is_solid(const Scene& scene) { return scene.fill.ratio >= 1.0; }

// The rule below in a line; its reasons are in each branch.
const char* auto_rule_description() {
    return "the cheapest model the scene needs: rigid for an empty or a full shell, going on as a free rigid body "
           "where it would lift off or slip; grains for a partly filled one";
}

namespace {

ModelChoice apply_rule(const Scene& scene) {
    ModelChoice c;
    // A curved track changes nothing here: the rigid model and the free body follow its local slope.
    if (scene.fill.ratio == 0.0) {
        c.model = Model::rigid;
        c.then = Model::grains;
        // A line or two as `polyroll run` prints it; docs/physics.md says the rest.
        c.reason =
            "empty shell: the rigid impact model is its exact limit (free to fly and slide), Box2D only at "
            "contacts it does not model (docs/physics.md)";
    } else if (fill_is_solid(scene)) {
        c.model = Model::rigid;
        c.then = Model::grains;
        c.reason =
            "full shell: its grains have no room to move, so shell and fill are one rigid polygon and the rigid "
            "impact model is its exact limit (free to fly and slide), Box2D only at contacts it does not model "
            "(docs/physics.md)";
    } else {
        // docs/tradeoff/tradeoff.md, over its 21 scenes against the reference.
        c.model = Model::grains;
        c.reason =
            "partly filled: the reduced models miss its terminal velocity by 27% (rigid) and 34% (segments), the "
            "grains by 5.6% (trade study: docs/tradeoff/tradeoff.md)";
    }
    return c;
}

// The registry's row says whether auto may use a model (ModelTraits::auto_may_pick): a rule that
// names another is a mistake in this file, not in the scene.
Model allowed(Model m) {
    if (!model_traits(m).auto_may_pick)
        throw std::logic_error("auto's rule picked the " + to_string(m) + " model, which the model registry keeps from it");
    return m;
}

}  // namespace

ModelChoice choose_model(const Scene& scene) {
    ModelChoice c = apply_rule(scene);
    c.model = allowed(c.model);
    if (c.then) c.then = allowed(*c.then);
    return c;
}

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
        auto flying = continue_as_free_body(scene_, run_->hand_over());
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
