// Building the Box2D world of a scene from its parts (world_parts.h): see world_builder.h.
#include "sim/grains/world_builder.h"

#include <cmath>

#include "sim/grains/contact_values.h"
#include "sim/grains/lid_friction.h"
#include "sim/grains/moving_frame.h"
#include "sim/geometry/ramp_profile.h"
#include "sim/grains/world_parts.h"

namespace polyroll {

namespace {
BodyKind kind_of(b2Fixture* f) { return static_cast<BodyKind>(f->GetBody()->GetUserData().pointer); }
}  // namespace

void ContactMaterials::BeginContact(b2Contact* contact) {
    const BodyKind a = kind_of(contact->GetFixtureA()), b = kind_of(contact->GetFixtureB());
    auto is = [&](BodyKind x, BodyKind y) { return (a == x && b == y) || (a == y && b == x); };
    if (is(BodyKind::shell, BodyKind::ramp)) {
        contact->SetFriction(static_cast<float>(scene_.ramp.friction));
        contact->SetRestitution(static_cast<float>(scene_.ramp.restitution));
    } else if (is(BodyKind::grain, BodyKind::shell)) {
        contact->SetFriction(static_cast<float>(disc_wall_friction(scene_)));
        contact->SetRestitution(static_cast<float>(disc_restitution(scene_)));
    }
    // Grain on grain: both fixtures carry the same values (contact_values.h), which Box2D's mixing keeps.
}

void SimWorld::step() {
    const double engine_step_s = 1.0 / (scene.fidelity.step_hz * scene.fidelity.substeps);
    const float dt = static_cast<float>(engine_step_s);
    for (int i = 0; i < scene.fidelity.substeps; ++i) {
        for (const ForceHook& hook : force_hooks) hook(*this, engine_step_s);
        step_in_frame(*this, dt, frame_velocity_units(*this));
    }
}

namespace {
// A curved track (ramp_profile.h): gravity turned to the local slope under the shell before each
// engine step, the grains seeing the shell's (they lie within a few centimetres of its centre, a
// few hundredths of a degree on these tracks). First among the hooks, so the others see it.
void turn_gravity_to_track(SimWorld& w, double /*engine_step_s*/) {
    const double x_m = w.units.to_m(w.shell->GetPosition().x);
    w.gravity_m_s2 = gravity_at_m_s2(w.scene.ramp, w.scene.run.gravity_m_s2, x_m);
    w.world->SetGravity(world_parts::to_b2(w.gravity_m_s2, w.units));
}
}  // namespace

namespace world_parts {

std::unique_ptr<SimWorld> empty_world(const Scene& scene, std::vector<ForceHook> hooks) {
    auto w = std::make_unique<SimWorld>();
    w->scene = scene;
    w->units = choose_engine_units(scene);
    w->shell_props = shell_properties(scene.shell);
    w->outer_local_m = shell_outer_polygon_m(scene.shell);
    w->inner_local_m = shell_inner_polygon_m(scene.shell);
    w->force_hooks = std::move(hooks);
    // The scene's own terms the contacts in the plane do not give, each left out when switched off.
    if (ramp_is_curved(scene.ramp)) w->force_hooks.insert(w->force_hooks.begin(), turn_gravity_to_track);
    if (scene.fill.material.lid_friction > 0.0 && scene.fill.ratio > 0.0) w->force_hooks.emplace_back(apply_lid_friction);

    // Until the first step turns it (a curved track), gravity as at the release.
    w->gravity_m_s2 = gravity_at_m_s2(scene.ramp, scene.run.gravity_m_s2, release_pivot_x_m(w->shell_props));
    // The run ends when the front of the polygon reaches the ramp's end.
    w->end_centre_x_m = end_centre_x_m(scene, w->shell_props);

    w->materials = std::make_unique<ContactMaterials>(w->scene);
    w->world = std::make_unique<b2World>(to_b2(w->gravity_m_s2, w->units));
    w->world->SetContactListener(w->materials.get());
    if (scene.fidelity.contacts == GrainContacts::near) {
        // A pair is given its contact within Box2D's own length tolerance of touching, and keeps it
        // until twice that apart: the reach decides only how often a contact is made and unmade,
        // never which pairs touch (near_pairs.h).
        w->near_pairs = std::make_unique<NearPairs>(b2_linearSlop, 2.0f * b2_linearSlop);
        w->world->SetContactFilter(w->near_pairs.get());
    }
    w->world->SetAllowSleeping(true);
    // Continuous collision in Box2D 2.4 only guards dynamic-vs-static pairs, here the shell on the
    // ramp. The ramp is 5 cm thick and the tracker stops any run whose shell nears 1.6 engine
    // units (at most 1.6 cm) per step, so the shell cannot pass through it; the
    // time-of-impact sub-steps cost about 10% of the default scene and, measured, moved the
    // rigid-impact energy ratios of empty shells further from the model (0.7-1.0% against 0.2-0.7%).
    w->world->SetContinuousPhysics(false);
    return w;
}

}  // namespace world_parts

std::unique_ptr<SimWorld> build_world(const Scene& scene, std::vector<ForceHook> hooks) {
    using namespace world_parts;
    std::unique_ptr<SimWorld> w = empty_world(scene, std::move(hooks));
    add_ramp(*w);
    const ShellPose pose = rounded_pose(*w, pour_pose(scene, w->shell_props));
    add_shell(*w, pose);  // held static while the grains settle
    pour_grains(*w, pose);
    settle_grains(*w);  // and, for the tipped release, turns shell and pile onto the vertex
    release_shell(*w, {0.0, 0.0}, 0.0);
    // Measure from where the engine holds the shell (floats), so the first row reads exactly 0.
    w->start_centre_x_m = w->units.to_m(w->shell->GetPosition().x);
    return w;
}

std::unique_ptr<SimWorld> build_world_from(const Scene& scene, const ShellState& shell, double start_centre_x_m,
                                           std::vector<ForceHook> hooks) {
    using namespace world_parts;
    std::unique_ptr<SimWorld> w = empty_world(scene, std::move(hooks));
    add_ramp(*w);
    const ShellPose pose = rounded_pose(*w, shell.pose);
    add_shell(*w, pose);
    pour_grains(*w, pose);
    release_shell(*w, shell.velocity_m_s, shell.angular_velocity_rad_s);
    // The grains move with the shell as one rigid body: v = v_centre + omega x (p - centre).
    const EngineUnits& u = w->units;
    const b2Vec2 centre = w->shell->GetPosition();
    for (b2Body* b : w->grains) {
        const b2Vec2 r = b->GetPosition() - centre;
        const double omega = shell.angular_velocity_rad_s;
        b->SetLinearVelocity({static_cast<float>(u.to_units(shell.velocity_m_s.x) - omega * r.y),
                              static_cast<float>(u.to_units(shell.velocity_m_s.y) + omega * r.x)});
        b->SetAngularVelocity(static_cast<float>(omega));
    }
    w->start_centre_x_m = start_centre_x_m;
    return w;
}

}  // namespace polyroll
