// A run computed whole at once (the reduced models, the free rigid body), shown in the tracker's
// steps: what has happened by a time, and the first step at which the run has ended.
#pragma once

#include <optional>
#include <vector>

#include "sim/geometry/geometry.h"
#include "sim/measurements.h"
#include "sim/model_run.h"

namespace polyroll::models {

// Moves the rows and impacts of `whole` up to `time_s` into `shown`; once `finished`, `shown` is all
// of `whole` (the behaviour, distance and terminal velocity are known only then).
void reveal_up_to(Measurements& shown, const Measurements& whole, double time_s, bool finished);

// The first tracker step, not before `from_step`, at or after `end_time_s`: computed rather than
// counted up to (counting ten thousand steps one by one cost about a third of a segment-model run on
// the default scene). `from_step` if there is no end to jump to.
long first_step_at_end(double end_time_s, double step_hz, long from_step);

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
