// The lanes of the sandbox: one to four runs of any model (ModelRun, from the model registry) built
// on worker threads (thousands of grains take seconds to pour and settle, and the window must keep
// answering), started together once all are built, and stepped together in fixed steps up to the
// clock's target within a wall-time budget.
// Numerical trouble in any lane (the tracker's divergence, or a non-finite state) stops them all
// with a message and a suggestion.
#pragma once

#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/model_run.h"
#include "sim/scene/scene.h"

namespace polyroll::app {

struct AdvanceResult {
    long steps = 0;
    bool budget_hit = false;
    double reached_s = 0.0;  // the slowest unfinished lane's time (or the latest, once all ended)
    // The work done, in cost units (sim/run_cost.h: engine_step_units per engine step), summed over
    // the steps taken. The physics budget measures its seconds per cost unit from it.
    double cost_units = 0.0;
};

class LaneSet {
public:
    ~LaneSet();

    // Throws away the current lanes and starts building these scenes (validated) in the background.
    void rebuild(const std::vector<Scene>& scenes);
    // Builds synchronously (tests, captures that must not start before the scene exists).
    void wait_until_built();
    // Takes in finished builds; call once per frame. Returns true when the lanes just became ready.
    bool poll();

    bool building() const { return !pending_.empty(); }
    bool ready() const { return !lanes_.empty() && pending_.empty(); }
    const std::string& build_error() const { return build_error_; }

    size_t size() const { return lanes_.size(); }
    ModelRun& lane(size_t i) { return *lanes_[i]; }
    const ModelRun& lane(size_t i) const { return *lanes_[i]; }

    // Steps every unfinished lane until it reaches target_s, round robin so that all move together,
    // stopping early when now() - start passes budget_s. Does nothing while troubled.
    AdvanceResult advance_to(double target_s, double budget_s, const std::function<double()>& now_s);
    // One tracker step of every unfinished lane.
    void step_once();
    bool all_finished() const;
    double time_s() const;  // the furthest lane's time

    // The first lane's numerical trouble, with a suggestion; empty while all is well. Checked after
    // every step batch, and by the window before it draws a snapshot.
    const std::optional<std::string>& trouble() const { return trouble_; }
    void check_trouble();
    // The window found lane i's snapshot not finite (a NaN among the grains): stop, as for divergence.
    void report_non_finite(size_t i);

private:
    std::vector<std::unique_ptr<ModelRun>> lanes_;
    std::vector<std::future<std::unique_ptr<ModelRun>>> pending_;
    // Builds overtaken by a newer rebuild: kept until they finish so no thread is left behind.
    std::vector<std::future<std::unique_ptr<ModelRun>>> abandoned_;
    std::string build_error_;
    std::optional<std::string> trouble_;
};

}  // namespace polyroll::app
