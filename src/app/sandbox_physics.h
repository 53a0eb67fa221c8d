// The sandbox's physics side: the lanes, the real-time clock and the transport (playing, running to
// the end), changed only by run(), which the physics worker calls with a frame's requests. The UI
// reads lanes() and clock() only between jobs, while the worker is idle, and learns what a job did
// from its PhysicsOutcome. No GLFW or ImGui here.
// The physics budget (model_budget.h) lives here too, as an offer only: each restart builds the
// scenes as asked, or the cheaper level the user picked, and never anything else; what this machine
// measures changes how fast the run plays and which cheaper model the panel offers, never the run.
#pragma once

#include <functional>

#include "app/lane_set.h"
#include "app/model_budget.h"
#include "app/physics_requests.h"
#include "app/sim_clock.h"

namespace polyroll::app {

class SandboxPhysics {
public:
    // `fixed_frames`: a --frames capture, whose every frame advances kCaptureFrameDtS with no wall-time
    // budget, so it shows the same moment on any machine. `now_s` is the wall clock the budgets use.
    SandboxPhysics(bool fixed_frames, std::function<double()> now_s);

    // Applies the requests' commands, then, for a frame's job, takes in finished builds and steps the
    // lanes as far as the clock (or the run to the end) asks within the frame's budget.
    PhysicsOutcome run(const PhysicsRequests& requests);

    const LaneSet& lanes() const { return lanes_; }
    const SimClock& clock() const { return clock_; }
    // The model the lanes step (the scenes as asked, or the level picked), and the cheaper model the
    // budget offers for real time (read between jobs, as lanes()).
    const BudgetChoice& budget_choice() const { return choice_; }
    const BudgetChoice& budget_offer() const { return offer_; }
    // The seconds per cost unit (sim/run_cost.h) measured in this window, 0 until a heavy enough scene has played
    // long enough (kBudgetMinCostUnitsPerS).
    double measured_s_per_cost_unit() const { return measured_cost_; }

private:
    void apply(const PhysicsRequests& r, PhysicsOutcome& out);
    void step_frame(double wall_dt_s, PhysicsOutcome& out);
    void build_chosen();
    // After a playing frame: learns the seconds per cost unit, which update the offer (never the lanes).
    void measure(double wall_dt_s, double sim_dt_s, double physics_s, double cost_units);
    void update_offer();

    bool fixed_frames_;
    std::function<double()> now_s_;
    LaneSet lanes_;
    SimClock clock_;
    bool playing_ = false;
    bool running_to_end_ = false;

    // The budget.
    int model_level_ = -1;      // the user's pick: -1 the scenes as asked
    std::vector<Scene> asked_;  // the scenes as the controls asked for them
    BudgetChoice choice_, offer_;
    double measured_cost_ = 0.0;
    // Since the build: wall, simulated and physics time, and the work done in grain engine steps.
    double played_wall_s_ = 0.0, played_sim_s_ = 0.0, played_physics_s_ = 0.0, played_cost_units_ = 0.0;
};

}  // namespace polyroll::app
