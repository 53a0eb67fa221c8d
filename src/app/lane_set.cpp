// The sandbox's lanes: see lane_set.h.
#include "app/lane_set.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "app/background_build.h"
#include "app/divergence.h"
#include "app/model_budget.h"
#include "sim/model_registry.h"
#include "sim/run_cost.h"

namespace polyroll::app {

LaneSet::~LaneSet() = default;  // the futures wait for their threads

void LaneSet::rebuild(const std::vector<Scene>& scenes) {
    for (auto& f : pending_) abandoned_.push_back(std::move(f));
    pending_.clear();
    lanes_.clear();
    build_error_.clear();
    trouble_.reset();
    for (const Scene& s : scenes)
        pending_.push_back(build_in_background([s] { return start_run(s); }));
}

void LaneSet::wait_until_built() {
    for (auto& f : pending_) f.wait();
    poll();
}

bool LaneSet::poll() {
    std::erase_if(abandoned_, [](auto& f) { return f.wait_for(std::chrono::seconds(0)) == std::future_status::ready; });
    if (pending_.empty()) return false;
    for (auto& f : pending_)
        if (f.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
    // All built: the lanes start together.
    std::vector<std::unique_ptr<ModelRun>> built;
    for (auto& f : pending_) {
        try {
            built.push_back(f.get());
        } catch (const std::exception& e) {
            if (build_error_.empty()) build_error_ = e.what();
        }
    }
    pending_.clear();
    if (!build_error_.empty()) return false;
    lanes_ = std::move(built);
    check_trouble();
    return true;
}

AdvanceResult LaneSet::advance_to(double target_s, double budget_s, const std::function<double()>& now_s) {
    AdvanceResult r;
    if (lanes_.empty() || trouble_) return r;
    const double start = now_s();
    bool any = true;
    while (any) {
        any = false;
        for (auto& lane : lanes_) {
            if (lane->finished() || lane->time_s() + 0.5 * lane->step_s() > target_s) continue;
            lane->step();
            ++r.steps;
            r.cost_units += engine_step_units(lane->grains(), lane->scene().fidelity) * lane->scene().fidelity.substeps;
            any = true;
        }
        if (any && now_s() - start >= budget_s) {
            r.budget_hit = true;
            break;
        }
    }
    check_trouble();
    r.reached_s = time_s();
    for (const auto& lane : lanes_)
        if (!lane->finished()) r.reached_s = std::min(r.reached_s, lane->time_s());
    return r;
}

void LaneSet::step_once() {
    if (trouble_) return;
    for (auto& lane : lanes_)
        if (!lane->finished()) lane->step();
    check_trouble();
}

bool LaneSet::all_finished() const {
    if (lanes_.empty()) return false;
    return std::all_of(lanes_.begin(), lanes_.end(), [](const auto& l) { return l->finished(); });
}

double LaneSet::time_s() const {
    double t = 0.0;
    for (const auto& lane : lanes_) t = std::max(t, lane->time_s());
    return t;
}

void LaneSet::check_trouble() {
    if (trouble_) return;
    for (size_t i = 0; i < lanes_.size(); ++i) {
        const Measurements& m = lanes_[i]->measured();
        if (m.behaviour == Behaviour::diverged) {
            trouble_ = trouble_message(static_cast<int>(i) + 1, lanes_[i]->scene(), lanes_[i]->time_s(), m.divergence);
            return;
        }
        const TrajectorySample& now = m.trajectory.empty() ? TrajectorySample{} : m.trajectory.back();
        if (!std::isfinite(now.position_m) || !std::isfinite(now.speed_m_s) || !std::isfinite(now.kinetic_J)) {
            trouble_ = trouble_message(static_cast<int>(i) + 1, lanes_[i]->scene(), lanes_[i]->time_s(),
                                       "a non-finite position, speed or energy");
            return;
        }
    }
}

}  // namespace polyroll::app

namespace polyroll::app {

void LaneSet::report_non_finite(size_t i) {
    if (trouble_ || i >= lanes_.size()) return;
    trouble_ = trouble_message(static_cast<int>(i) + 1, lanes_[i]->scene(), lanes_[i]->time_s(),
                               "a grain or the shell has a non-finite position or speed");
}

}  // namespace polyroll::app
