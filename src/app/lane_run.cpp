// A lane's run, live or played back: see lane_run.h.
#include "app/lane_run.h"

#include <algorithm>
#include <cmath>

#include "sim/fill_plan.h"
#include "sim/shell_properties.h"
#include "sim/world_builder.h"

namespace polyroll::app {

namespace {

// The grain simulation, stepped live.
class LiveLane final : public LaneRun {
public:
    explicit LiveLane(const Scene& scene) : sim_(scene) {}
    bool step() override { return sim_.step(); }
    bool finished() const override { return sim_.finished(); }
    double time_s() const override { return sim_.time_s(); }
    const Scene& scene() const override { return sim_.world().scene; }
    render::Snapshot snapshot() const override { return render::take_snapshot(sim_); }
    const Measurements& measured() const override { return sim_.tracker().measurements(); }
    RunResult result() const override { return sim_.result(); }
    int grains() const override { return static_cast<int>(sim_.world().grains.size()); }

private:
    Simulation sim_;
};

// A reduced model's run, computed whole and revealed step by step.
class PlaybackLane final : public LaneRun {
public:
    explicit PlaybackLane(const Scene& scene) : scene_(scene), full_(run_scene(scene)) {
        // The pose is drawn from a run sampled at every tracker step, so the polygon turns smoothly;
        // the readouts, plots and files use the run at the scene's own sample rate, as polyroll run.
        Scene fine = scene;
        fine.run.sample_hz = scene.fidelity.step_hz;
        pose_track_ = run_scene(fine).measured.trajectory;
        outer_ = shell_outer_polygon_m(scene.shell);
        inner_ = shell_inner_polygon_m(scene.shell);
        shown_.behaviour = Behaviour::running;
        reveal();
    }
    bool step() override {
        if (finished()) return false;
        ++steps_;
        reveal();
        return !finished();
    }
    bool finished() const override { return time_s() >= full_.measured.end_time_s - 1e-12; }
    double time_s() const override { return static_cast<double>(steps_) / scene_.fidelity.step_hz; }
    const Scene& scene() const override { return scene_; }
    const Measurements& measured() const override { return shown_; }
    RunResult result() const override { return full_; }
    int grains() const override { return 0; }

    render::Snapshot snapshot() const override {
        render::Snapshot s;
        s.sides = scene_.shell.sides;
        s.fill_ratio = scene_.fill.ratio;
        s.ramp_angle_deg = scene_.ramp.angle_deg;
        s.ramp_length_m = scene_.ramp.length_m;
        s.material = scene_.fill.material.preset;
        s.ramp = scene_.ramp.preset;
        s.outer_local_m = outer_;
        s.inner_local_m = inner_;
        s.time_s = std::min(time_s(), full_.measured.end_time_s);
        const TrajectorySample now = sample_at(pose_track_, s.time_s);
        const ShellPose pose = rolling_pose(scene_, now.position_m, now.angle_deg);
        s.shell_centre_m = pose.centre_m;
        s.shell_angle_rad = pose.angle_rad;
        s.now = now;
        s.impacts = static_cast<int>(shown_.impacts.size());
        for (const TrajectorySample& t : shown_.trajectory) s.speed_history.push_back({t.time_s, t.speed_m_s});
        if (s.speed_history.empty() || s.speed_history.back().time_s < s.now.time_s)
            s.speed_history.push_back({s.now.time_s, s.now.speed_m_s});
        return s;
    }

private:
    static TrajectorySample sample_at(const std::vector<TrajectorySample>& track, double t) {
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

    // Moves what has happened by now from the full run into the shown measurements.
    void reveal() {
        const Measurements& m = full_.measured;
        const double t = time_s() + 1e-12;
        while (shown_.trajectory.size() < m.trajectory.size() && m.trajectory[shown_.trajectory.size()].time_s <= t)
            shown_.trajectory.push_back(m.trajectory[shown_.trajectory.size()]);
        while (shown_.impacts.size() < m.impacts.size() && m.impacts[shown_.impacts.size()].time_s <= t)
            shown_.impacts.push_back(m.impacts[shown_.impacts.size()]);
        if (finished()) {
            shown_ = m;  // the behaviour, distance and terminal velocity are known once it has ended
        } else if (!shown_.trajectory.empty()) {
            shown_.distance_m = shown_.trajectory.back().position_m;
            shown_.end_time_s = time_s();
        }
    }

    Scene scene_;
    RunResult full_;
    std::vector<TrajectorySample> pose_track_;
    std::vector<geom::Vec2> outer_, inner_;
    Measurements shown_;
    long steps_ = 0;
};

}  // namespace

ShellPose rolling_pose(const Scene& scene, double position_m, double angle_deg) {
    const Pose release = release_pose(scene, shell_properties(scene.shell));
    ShellPose p;
    p.angle_rad = release.angle_rad - angle_deg * geom::kPi / 180.0;  // rolling down is clockwise
    double lowest = 0.0;
    bool first = true;
    for (const geom::Vec2& v : shell_outer_polygon_m(scene.shell)) {
        const double y = geom::rotate(v, p.angle_rad).y;
        if (first || y < lowest) lowest = y;
        first = false;
    }
    p.centre_m = {release.centre_m.x + position_m, -lowest};
    return p;
}

std::unique_ptr<LaneRun> make_lane_run(const Scene& scene) {
    if (scene.run.model == Model::grains) return std::make_unique<LiveLane>(scene);
    return std::make_unique<PlaybackLane>(scene);
}

}  // namespace polyroll::app
