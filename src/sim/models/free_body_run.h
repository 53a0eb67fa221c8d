// An empty shell's run after lift-off (free_body.h) as a ModelRun, carrying on the run another
// model handed over: computed whole at once, revealed in the tracker's steps like ReducedRun, so the
// window, the renderer and a further hand-over to Box2D see it as they see any run.
#pragma once

#include <mutex>
#include <optional>
#include <vector>

#include "sim/model_run.h"
#include "sim/models/free_body.h"

namespace polyroll::models {

class FreeBodyRun final : public ModelRun {
public:
    // `scene` has no fill (fill.ratio 0); `from` is the state of the model that ran before.
    FreeBodyRun(const Scene& scene, const HandOver& from);

    bool step() override;
    bool finished() const override;
    long steps() const override { return steps_; }
    const Scene& scene() const override { return scene_; }
    RunSnapshot snapshot() const override;
    const Measurements& measured() const override { return shown_; }
    RunResult result() const override;
    int grains() const override { return 0; }
    HandOver hand_over() const override;
    void run_to_end() override;

    // The tracker step at which to hand the shell to Box2D: the last one before the run met a contact
    // it does not model (unsupported_why), if it did.
    std::optional<long> hand_over_step() const { return hand_over_step_; }
    const std::string& unsupported_why() const { return full_.unsupported_why; }
    const FreeBodyMotion& run() const { return full_; }

private:
    // The state at every tracker step from the hand-over on, computed when first needed (drawing, a
    // hand-over): `polyroll run` never needs it.
    const FreeBodyMotion& fine() const;
    ShellState state_now() const;
    TrajectorySample sample_now() const;
    void reveal();

    Scene scene_;
    HandOver from_;
    FreeBody body_;
    double fill_mass_kg_ = 0.0;  // a full shell's fill, turning with it (0 for an empty shell)
    FreeBodyRules rules_;
    FreeBodyMotion full_;
    std::optional<long> hand_over_step_;
    mutable std::once_flag fine_once_;
    mutable FreeBodyMotion fine_;
    std::vector<geom::Vec2> outer_, inner_;
    Measurements shown_;
    long steps_ = 0;
};

}  // namespace polyroll::models
