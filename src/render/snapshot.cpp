// Copying a run's state out of Box2D: see snapshot.h.
#include "render/snapshot.h"

#include "sim/simulation.h"

namespace polyroll::render {

Snapshot take_snapshot(const Simulation& sim) {
    const SimWorld& w = sim.world();
    const EngineUnits& u = w.units;
    Snapshot s;
    s.sides = w.scene.shell.sides;
    s.fill_ratio = w.scene.fill.ratio;
    s.ramp_angle_deg = w.scene.ramp.angle_deg;
    s.ramp_length_m = w.scene.ramp.length_m;
    s.material = w.scene.fill.material.preset;
    s.ramp = w.scene.ramp.preset;
    s.outer_local_m = w.outer_local_m;
    s.inner_local_m = w.inner_local_m;

    s.time_s = sim.time_s();
    const b2Vec2 c = w.shell->GetPosition();
    s.shell_centre_m = {u.to_m(c.x), u.to_m(c.y)};
    s.shell_angle_rad = w.shell->GetAngle();
    s.grains.reserve(w.grains.size());
    for (const b2Body* b : w.grains) {
        const b2Vec2 p = b->GetPosition();
        const b2Fixture* f = b->GetFixtureList();
        GrainState g;
        g.position_m = {u.to_m(p.x), u.to_m(p.y)};
        g.radius_m = f ? u.to_m(f->GetShape()->m_radius) : 0.0;
        g.speed_m_s = u.to_m(b->GetLinearVelocity().Length());
        s.grains.push_back(g);
    }
    s.now = sim.tracker().current();
    const Measurements& m = sim.tracker().measurements();
    s.impacts = static_cast<int>(m.impacts.size());
    s.speed_history.reserve(m.trajectory.size() + 1);
    for (const TrajectorySample& t : m.trajectory) s.speed_history.push_back({t.time_s, t.speed_m_s});
    // The plot ends at the current instant even between trajectory samples.
    if (s.speed_history.empty() || s.speed_history.back().time_s < s.now.time_s)
        s.speed_history.push_back({s.now.time_s, s.now.speed_m_s});
    return s;
}

}  // namespace polyroll::render
