// The sandbox's physics side: see sandbox_physics.h.
#include "app/sandbox_physics.h"

#include <limits>
#include <utility>

#include "app/sandbox_settings.h"
#include "sim/errors.h"

namespace polyroll::app {

namespace {
constexpr double kNoBudget = std::numeric_limits<double>::infinity();
}

SandboxPhysics::SandboxPhysics(bool fixed_frames, std::function<double()> now_s)
    : fixed_frames_(fixed_frames), now_s_(std::move(now_s)) {}

PhysicsOutcome SandboxPhysics::run(const PhysicsRequests& requests) {
    const double t0 = now_s_();
    PhysicsOutcome out;
    apply(requests, out);
    if (requests.frame) {
        if (lanes_.poll()) {
            clock_.restart(0.0);
            out.built = true;
        }
        clock_.set_slow_divisor(requests.frame->slow_divisor);
        step_frame(requests.frame->wall_dt_s, out);
    }
    out.physics_s = now_s_() - t0;
    out.time_s = lanes_.time_s();
    out.playing = playing_;
    out.running_to_end = running_to_end_;
    out.build_failed = !lanes_.build_error().empty();
    out.finished = lanes_.all_finished();
    out.trouble = lanes_.trouble().has_value();
    return out;
}

void SandboxPhysics::apply(const PhysicsRequests& r, PhysicsOutcome& out) {
    if (r.non_finite_lane) lanes_.report_non_finite(*r.non_finite_lane);
    if (r.model_level) model_level_ = *r.model_level;
    if (r.restart_with) {
        asked_ = *r.restart_with;
        build_chosen();
        running_to_end_ = false;
        clock_.restart(0.0);
    }
    if (r.wait_until_built) {
        lanes_.wait_until_built();
        clock_.restart(0.0);
        out.built = lanes_.ready();
    }
    if (r.play && *r.play != playing_) {
        playing_ = *r.play;
        clock_.restart(lanes_.time_s());
    }
    if (r.step && lanes_.ready() && !lanes_.trouble()) {
        playing_ = false;
        out.steps += lanes_.advance_to(lanes_.time_s() + kSingleStepS, kNoBudget, now_s_).steps;
        clock_.restart(lanes_.time_s());
    }
    if (r.run_to_end && lanes_.ready() && !lanes_.all_finished() && !lanes_.trouble()) running_to_end_ = true;
}

void SandboxPhysics::step_frame(double wall_dt_s, PhysicsOutcome& out) {
    if (!lanes_.ready() || lanes_.trouble()) return;
    if (running_to_end_) {
        if (!lanes_.all_finished())
            out.steps += lanes_.advance_to(kNoBudget, kRunToEndBudgetPerFrameS, now_s_).steps;
        if (lanes_.all_finished() || lanes_.trouble()) {
            running_to_end_ = false;
            playing_ = false;
        }
        clock_.restart(lanes_.time_s());
        return;
    }
    if (!playing_ || lanes_.all_finished()) return;
    // A capture advances a fixed 1/60 s per frame with no budget, so it shows the same moment on any
    // machine; the window and the benchmark keep real time within the budget.
    const double dt = fixed_frames_ ? kCaptureFrameDtS : wall_dt_s;
    const double budget = fixed_frames_ ? kNoBudget : kPhysicsBudgetPerFrameS;
    clock_.advance(dt);
    const double t0 = now_s_(), sim0_s = lanes_.time_s();
    const AdvanceResult r = lanes_.advance_to(clock_.target_s(), budget, now_s_);
    out.steps += r.steps;
    clock_.frame_done(dt, r.reached_s, r.budget_hit);
    if (!fixed_frames_ && clock_.slow_divisor() == 1) measure(dt, lanes_.time_s() - sim0_s, now_s_() - t0, r.cost_units);
}

void SandboxPhysics::build_chosen() {
    const BudgetFigures& f = budget_figures();
    const bool measured = measured_cost_ > 0.0 && !fixed_frames_;
    const double cost = measured ? measured_cost_ : f.cost.engine_step_s;
    // The user's pick alone decides the model; a level that does not fit these scenes' shells (the
    // panel offers only those that do) falls back to the scenes as asked rather than refusing them.
    try {
        choice_ = picked_level(asked_, f, model_level_, cost, measured);
    } catch (const InputError&) {
        choice_ = picked_level(asked_, f, -1, cost, measured);
    }
    update_offer();
    lanes_.rebuild(apply_choice(asked_, f, choice_));
    played_wall_s_ = played_sim_s_ = played_physics_s_ = played_cost_units_ = 0.0;
}

void SandboxPhysics::update_offer() {
    // A capture (fixed frames) uses the asset's cost only, so it shows the same offer on any machine.
    const bool measured = measured_cost_ > 0.0 && !fixed_frames_;
    const BudgetFigures& f = budget_figures();
    offer_ = offered_level(asked_, f, measured ? measured_cost_ : f.cost.engine_step_s, measured);
}

void SandboxPhysics::measure(double wall_dt_s, double sim_dt_s, double physics_s, double cost_units) {
    played_wall_s_ += wall_dt_s;
    played_sim_s_ += sim_dt_s;
    played_physics_s_ += physics_s;
    played_cost_units_ += cost_units;
    if (played_wall_s_ < kBudgetMeasureS || played_cost_units_ <= 0.0 || played_sim_s_ <= 0.0) return;
    // Only a heavy scene's cost stands for the next scenes' (a few loose grains cost far less each).
    if (played_cost_units_ / played_sim_s_ < kBudgetMinCostUnitsPerS) return;
    // The scene's own cost on this computer: the offer follows it; the lanes go on as they are.
    measured_cost_ = played_physics_s_ / played_cost_units_;
    update_offer();
    played_wall_s_ = played_sim_s_ = played_physics_s_ = played_cost_units_ = 0.0;
}

}  // namespace polyroll::app
