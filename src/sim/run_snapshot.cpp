// The parts of a snapshot every model shares: see run_snapshot.h.
#include "sim/run_snapshot.h"

namespace polyroll {

RunSnapshot scene_snapshot(const Scene& scene, const std::vector<geom::Vec2>& outer_local_m,
                           const std::vector<geom::Vec2>& inner_local_m) {
    RunSnapshot s;
    s.sides = scene.shell.sides;
    s.fill_ratio = scene.fill.ratio;
    s.ramp_angle_deg = scene.ramp.angle_deg;
    s.ramp_length_m = scene.ramp.length_m;
    s.material = scene.fill.material.preset;
    s.ramp = scene.ramp.preset;
    s.outer_local_m = outer_local_m;
    s.inner_local_m = inner_local_m;
    return s;
}

void set_measured(RunSnapshot& s, const TrajectorySample& now, const Measurements& m) {
    s.now = now;
    s.impacts = static_cast<int>(m.impacts.size());
    s.speed_history.reserve(m.trajectory.size() + 1);
    for (const TrajectorySample& t : m.trajectory) s.speed_history.push_back({t.time_s, t.speed_m_s});
    if (s.speed_history.empty() || s.speed_history.back().time_s < s.now.time_s)
        s.speed_history.push_back({s.now.time_s, s.now.speed_m_s});
}

}  // namespace polyroll
