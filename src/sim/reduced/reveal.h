// A run computed whole at once (the reduced models, the free rigid body), shown in the tracker's
// steps (sim/reveal_steps.h, which the 3D reference shares).
#pragma once

#include <optional>
#include <vector>

#include "sim/geometry/geometry.h"
#include "sim/measurements.h"
#include "sim/model_run.h"
#include "sim/reveal_steps.h"

namespace polyroll::models {

// The common part of a run computed whole at once and revealed step by step: the steps, the records
// shown so far, and the end (the whole run's end, or the step at which it hands the shell on). The
// derived run computes its whole run in its constructor, then calls reveal().
class RevealedRun : public ModelRun {
public:
    bool step() override;
    bool finished() const override;
    long steps() const override { return steps_; }
    const Scene& scene() const override { return scene_; }
    const Measurements& measured() const override { return shown_; }
    int grains() const override { return 0; }
    void run_to_end() override;

protected:
    // Starts at tracker step `first_step` with the records `shown` so far.
    RevealedRun(const Scene& scene, long first_step, Measurements shown);

    // All the records of the run, computed at once.
    virtual const Measurements& whole() const = 0;
    // The step at which the run hands the shell on before its end, if it does: it stops there.
    virtual std::optional<long> stop_step() const { return std::nullopt; }
    void reveal();
    // The scene's ramp and shell, to which the derived run adds the pose and the readouts.
    RunSnapshot scene_snapshot_now() const;

    Scene scene_;
    Measurements shown_;
    long steps_ = 0;

private:
    std::vector<geom::Vec2> outer_, inner_;
};

}  // namespace polyroll::models
