// A reduced model's run, revealed step by step: see reduced_run.h.
#include "sim/reduced/reduced_run.h"

#include <algorithm>
#include <cmath>

#include "sim/reduced/composite_body.h"
#include "sim/reduced/reduced_models.h"
#include "sim/reduced/reveal.h"
#include "sim/geometry/ramp_profile.h"
#include "sim/geometry/shell_pose.h"

namespace polyroll::models {

namespace {

TrajectorySample sample_at(const std::vector<TrajectorySample>& track, double t) {
    if (track.empty()) return {};
    auto it = std::lower_bound(track.begin(), track.end(), t,
                               [](const TrajectorySample& a, double v) { return a.time_s < v; });
    if (it == track.begin()) return track.front();
    if (it == track.end()) return track.back();
    const TrajectorySample& b = *it;
    const TrajectorySample& a = *(it - 1);
    const double f = b.time_s > a.time_s ? (t - a.time_s) / (b.time_s - a.time_s) : 1.0;
    auto mix = [f](double x, double y) { return x + f * (y - x); };
    TrajectorySample s;
    s.time_s = t;
    s.position_m = mix(a.position_m, b.position_m);
    s.speed_m_s = mix(a.speed_m_s, b.speed_m_s);
    s.angle_deg = mix(a.angle_deg, b.angle_deg);
    s.kinetic_J = mix(a.kinetic_J, b.kinetic_J);
    s.potential_J = mix(a.potential_J, b.potential_J);
    s.dissipated_J = mix(a.dissipated_J, b.dissipated_J);
    return s;
}

}  // namespace

ReducedRun::ReducedRun(const Scene& scene, FillMotion fill, bool until_invalid)
    : RevealedRun(scene, 0, Measurements{}),
      fill_(fill),
      until_invalid_(until_invalid),
      full_(run_reduced_model(scene, fill, until_invalid)) {
    reveal();
}

const std::vector<TrajectorySample>& ReducedRun::pose_track() const {
    std::call_once(pose_once_, [this] {
        Scene fine = scene_;
        fine.run.sample_hz = scene_.fidelity.step_hz;
        pose_track_ = run_reduced_model(fine, fill_, until_invalid_).measured.trajectory;
        pose_done_ = true;
    });
    return pose_track_;
}

TrajectorySample ReducedRun::now() const {
    return sample_at(pose_track(), std::min(time_s(), full_.measured.end_time_s));
}

RunSnapshot ReducedRun::snapshot() const {
    RunSnapshot s = scene_snapshot_now();
    s.time_s = std::min(time_s(), full_.measured.end_time_s);
    const TrajectorySample now = sample_at(pose_track(), s.time_s);
    const ShellPose pose = rolling_pose(scene_, now.position_m, now.angle_deg);
    s.shell_centre_m = pose.centre_m;
    s.shell_angle_rad = pose.angle_rad;
    set_measured(s, now, shown_);
    s.fill_region_local_m = fill_region_at(s.inner_local_m, s.time_s);
    return s;
}

std::vector<geom::Vec2> ReducedRun::fill_region_at(const std::vector<geom::Vec2>& inner, double time_s) const {
    if (scene_.fill.ratio <= 0.0) return {};
    // The frozen fill keeps its shape at release; the levelled one takes the level of its last impact.
    double levelled_at_s = 0.0;
    if (fill_ == FillMotion::relevel)
        for (const FaceImpact& i : shown_.impacts)
            if (i.time_s <= time_s) levelled_at_s = i.time_s;
    const TrajectorySample at = sample_at(pose_track(), levelled_at_s);
    const ShellPose then = rolling_pose(scene_, at.position_m, at.angle_deg);
    const geom::Vec2 g = gravity_at_m_s2(scene_.ramp, scene_.run.gravity_m_s2, then.centre_m.x);
    const geom::Vec2 up_ramp = (-1.0 / geom::length(g)) * g;
    return fill_segments(inner, geom::rotate(up_ramp, -then.angle_rad), std::min(scene_.fill.ratio, 1.0), 1.0).region;
}

TrajectorySample ReducedRun::state_for_hand_over() const {
    // Without the pose track (a run nobody drew), the same model run again up to now ends with the
    // state now: a tenth of the cost of sampling every tracker step of the whole run (measured on
    // `polyroll bench --auto`, where that sampling was most of auto's time on a shell that lifts off).
    if (finished() || pose_done_.load()) return now();
    Scene cut = scene_;
    cut.run.time_limit_s = time_s();
    const RunResult upto = run_reduced_model(cut, fill_, until_invalid_);
    if (upto.measured.trajectory.empty()) return now();
    TrajectorySample last = upto.measured.trajectory.back();
    last.time_s = time_s();
    return last;
}

HandOver ReducedRun::hand_over() const {
    const TrajectorySample n = state_for_hand_over();
    return counted_hand_over(steps_, rolling_state(scene_, n), release_pose(scene_, full_.shell), shown_,
                             n.potential_J);
}

}  // namespace polyroll::models
