// An empty shell's run after lift-off (free_body.h) as a ModelRun, carrying on the run another
// model handed over: computed whole at once, revealed in the tracker's steps like ReducedRun, so the
// window, the renderer and a further hand-over to Box2D see it as they see any run.
#pragma once

#include <optional>
#include <vector>

#include "sim/reduced/free_body.h"
#include "sim/reduced/reveal.h"

namespace polyroll::models {

// Where a free body carries on a run another model hands over: the time (its steps at `step_hz`),
// the shell's state and the records so far.
FreeBodyStart free_body_start(const HandOver& from, double step_hz);

class FreeBodyRun final : public RevealedRun {
public:
    // `scene` has no fill (fill.ratio 0); `from` is the state of the model that ran before.
    FreeBodyRun(const Scene& scene, const HandOver& from);

    RunSnapshot snapshot() const override;
    RunResult result() const override;
    HandOver hand_over() const override;

    // The tracker step at which to hand the shell to Box2D: the last one before the run met a contact
    // it does not model (unsupported_why), if it did.
    std::optional<long> hand_over_step() const { return hand_over_step_; }
    const std::string& unsupported_why() const { return full_.unsupported_why; }
    const FreeBodyMotion& run() const { return full_; }

private:
    const Measurements& whole() const override { return full_.measured; }
    std::optional<long> stop_step() const override { return hand_over_step_; }
    // The run's row at the current step, from its dense output (FreeBodyMotion::row_at_step); none
    // before its first step.
    std::optional<FreeBodyRow> row_now() const;
    ShellState state_now() const;
    TrajectorySample sample_now() const;

    HandOver from_;
    FreeBody body_;
    double fill_mass_kg_ = 0.0;  // a full shell's fill, turning with it (0 for an empty shell)
    FreeBodyMotion full_;
    std::optional<long> hand_over_step_;
};

}  // namespace polyroll::models
