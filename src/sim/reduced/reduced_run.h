// A reduced model's run as a ModelRun: the model computes the whole run at once (in about a
// millisecond), and the run reveals it in the tracker's fixed steps, so a window, a renderer or a
// hand-over sees it as it would see the grain simulation. The shell's pose is drawn from the same
// run sampled at every tracker step, so the polygon turns smoothly between the scene's samples.
#pragma once

#include <atomic>
#include <mutex>
#include <vector>

#include "sim/reduced/reveal.h"
#include "sim/reduced/rolling_polygon.h"

namespace polyroll::models {

class ReducedRun final : public RevealedRun {
public:
    // `until_invalid`: the run ends where the model stops holding (for `--model auto`, which hands
    // the shell on at the step before).
    ReducedRun(const Scene& scene, FillMotion fill, bool until_invalid = false);

    RunSnapshot snapshot() const override;
    RunResult result() const override { return full_; }
    HandOver hand_over() const override;

private:
    const Measurements& whole() const override { return full_.measured; }
    // The pose track is computed the first time it is needed: `polyroll run` never draws.
    const std::vector<TrajectorySample>& pose_track() const;
    TrajectorySample now() const;  // at time_s(), held at the end
    TrajectorySample state_for_hand_over() const;  // now(), without computing the pose track
    // The fill's region at `time_s` in the shell's frame (RunSnapshot::fill_region_local_m), inside
    // the shell's `inner` polygon.
    std::vector<geom::Vec2> fill_region_at(const std::vector<geom::Vec2>& inner, double time_s) const;

    FillMotion fill_;
    bool until_invalid_ = false;
    RunResult full_;
    mutable std::once_flag pose_once_;
    mutable std::vector<TrajectorySample> pose_track_;
    mutable std::atomic<bool> pose_done_{false};
};

}  // namespace polyroll::models
