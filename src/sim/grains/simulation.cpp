// The grain model's run: see simulation.h.
#include "sim/grains/simulation.h"

#include <nlohmann/json.hpp>

#include "sim/grains/tracker.h"
#include "sim/grains/world_builder.h"

namespace polyroll {

Simulation::Simulation(const Scene& scene, std::vector<ForceHook> hooks)
    : world_(build_world(scene, std::move(hooks))) {
    tracker_ = std::make_unique<Tracker>(*world_);
    tracker_->observe(0);  // the release state is the trajectory's first row
}

Simulation::Simulation(const Scene& scene, const HandOver& from, std::vector<ForceHook> hooks)
    : world_(build_world_from(scene, from.shell, from.release.centre_m.x, std::move(hooks))), steps_(from.steps) {
    tracker_ = std::make_unique<Tracker>(*world_);
    tracker_->continue_from(from);
}

Simulation::~Simulation() = default;

const Scene& Simulation::scene() const { return world_->scene; }
const Measurements& Simulation::measured() const { return tracker_->measurements(); }
int Simulation::grains() const { return static_cast<int>(world_->grains.size()); }

bool Simulation::finished() const { return tracker_->measurements().behaviour != Behaviour::running; }

bool Simulation::step() {
    if (finished()) return false;
    world_->step();
    ++steps_;
    return tracker_->observe(steps_);
}

RunResult Simulation::result() const {
    RunResult r;
    r.scene = world_->scene;
    r.shell = world_->shell_props;
    r.measured = tracker_->measurements();
    r.grains = static_cast<int>(world_->grains.size());
    for (const PlannedGrain& g : world_->fill.grains) r.fill_mass_kg += g.mass_kg;
    r.settle_time_s = world_->settle_time_s;
    r.settled = world_->settled;
    r.balance_correction_deg = world_->balance_correction_deg;
    r.steps = steps_;
    r.model_blocks.json()["engine"] = engine_block(world_->units, r.scene.fidelity);
    return r;
}

RunSnapshot Simulation::snapshot() const {
    const SimWorld& w = *world_;
    const EngineUnits& u = w.units;
    RunSnapshot s = scene_snapshot(w.scene, w.outer_local_m, w.inner_local_m);
    s.time_s = time_s();
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
    set_measured(s, tracker_->current(), tracker_->measurements());
    return s;
}

ShellNow Simulation::shell_now() const {
    const EngineUnits& u = world_->units;
    const b2Vec2 c = world_->shell->GetPosition();
    return {time_s(), {u.to_m(c.x), u.to_m(c.y)}, world_->shell->GetAngle(), tracker_->current(),
            static_cast<int>(tracker_->measurements().impacts.size())};
}

HandOver Simulation::hand_over() const {
    const SimWorld& w = *world_;
    const EngineUnits& u = w.units;
    HandOver h;
    h.steps = steps_;
    const b2Vec2 c = w.shell->GetPosition(), v = w.shell->GetLinearVelocity();
    // The engine holds the shell two skins above the surface (add_shell); the pose is the polygon's.
    h.shell.pose.centre_m = {u.to_m(c.x), u.to_m(c.y - 2.0f * b2_polygonRadius)};
    h.shell.pose.angle_rad = w.shell->GetAngle();
    h.shell.velocity_m_s = {u.to_m(v.x), u.to_m(v.y)};
    h.shell.angular_velocity_rad_s = w.shell->GetAngularVelocity();
    h.release.centre_m = {w.start_centre_x_m, release_pose(w.scene, w.shell_props).centre_m.y};
    h.release.angle_rad = tracker_->start_angle_rad();
    h.measured = tracker_->measurements();
    h.landed_vertex = tracker_->landed_vertex();
    h.potential_J = tracker_->current().potential_J;
    return h;
}

}  // namespace polyroll
