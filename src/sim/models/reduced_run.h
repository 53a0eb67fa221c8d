// A reduced model's run as a ModelRun: the model computes the whole run at once (in about a
// millisecond), and the run reveals it in the tracker's fixed steps, so a window, a renderer or a
// hand-over sees it as it would see the grain simulation. The shell's pose is drawn from the same
// run sampled at every tracker step, so the polygon turns smoothly between the scene's samples.
#pragma once

#include <atomic>
#include <mutex>
#include <vector>

#include "sim/model_run.h"
#include "sim/models/rolling_polygon.h"

namespace polyroll::models {

class ReducedRun final : public ModelRun {
public:
    // `until_invalid`: the run ends where the model stops holding (for `--model auto`, which hands
    // the shell on at the step before).
    ReducedRun(const Scene& scene, FillMotion fill, bool until_invalid = false);

    bool step() override;
    bool finished() const override;
    long steps() const override { return steps_; }
    const Scene& scene() const override { return scene_; }
    RunSnapshot snapshot() const override;
    const Measurements& measured() const override { return shown_; }
    RunResult result() const override { return full_; }
    int grains() const override { return 0; }
    HandOver hand_over() const override;
    void run_to_end() override;

private:
    // The pose track is computed the first time it is needed: `polyroll run` never draws.
    const std::vector<TrajectorySample>& pose_track() const;
    TrajectorySample now() const;  // at time_s(), held at the end
    TrajectorySample state_for_hand_over() const;  // now(), without computing the pose track
    void reveal();

    Scene scene_;
    FillMotion fill_;
    bool until_invalid_ = false;
    RunResult full_;
    mutable std::once_flag pose_once_;
    mutable std::vector<TrajectorySample> pose_track_;
    mutable std::atomic<bool> pose_done_{false};
    std::vector<geom::Vec2> outer_, inner_;
    Measurements shown_;
    long steps_ = 0;
};

}  // namespace polyroll::models
