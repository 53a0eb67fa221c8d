// The grains poured into the held shell and settled: see world_parts.h.
#include "sim/grains/contact_values.h"
#include "sim/grains/world_parts.h"

#include <algorithm>
#include <cmath>

#include "sim/run_progress.h"

namespace polyroll::world_parts {

using geom::Vec2;

namespace {

// The slope the pile settles on: the track's at the release (the ramp's angle on a straight track).
double ramp_angle_rad(const SimWorld& w) { return release_slope_deg(w.scene, w.shell_props) * geom::kPi / 180.0; }

// Turns the shell and every grain together, as one rigid body, by `delta_rad` about `pivot`.
void turn_all_about(SimWorld& w, b2Vec2 pivot, double delta_rad) {
    auto turn = [&](b2Body* b) {
        const b2Vec2 rel = b->GetPosition() - pivot;
        const geom::Vec2 r = geom::rotate({rel.x, rel.y}, delta_rad);
        b->SetTransform(pivot + b2Vec2(static_cast<float>(r.x), static_cast<float>(r.y)),
                        b->GetAngle() + static_cast<float>(delta_rad));
    };
    turn(w.shell);
    for (b2Body* b : w.grains) turn(b);
}

// A settled pile is never quite symmetric, and a full polygon's fill outweighs its shell several
// times: a millimetre's lean of the pile moves the whole body's centre of mass further than the
// release tilt does. The hand that holds the polygon on its vertex feels the balance of the whole
// thing, so the shell and its settled grains are turned together about the pivot until the centre of
// mass of everything lies release.tilt_deg past the vertical through the pivot, downhill. Returns the
// turn made, in degrees (counter-clockwise positive).
double balance_on_pivot(SimWorld& w, double theta) {
    const EngineUnits& u = w.units;
    const double shell_mass = w.shell_props.mass_kg;
    const b2Vec2 centre = w.shell->GetPosition();
    double mx = shell_mass * centre.x, my = shell_mass * centre.y, mass = shell_mass;
    for (const b2Body* b : w.grains) {
        mx += b->GetMass() * b->GetPosition().x;
        my += b->GetMass() * b->GetPosition().y;
        mass += b->GetMass();
    }
    const geom::Vec2 v1 = w.outer_local_m[1];
    const b2Vec2 pivot = w.shell->GetWorldPoint(to_b2(v1, u));
    const geom::Vec2 lean = {mx / mass - pivot.x, my / mass - pivot.y};
    const geom::Vec2 up = {-std::sin(theta), std::cos(theta)};
    const double lean_rad = std::atan2(geom::cross(up, lean), geom::dot(up, lean));  // + is uphill
    const double target_rad = -w.scene.release.tilt_deg * geom::kPi / 180.0;
    // Keep both neighbouring faces off the ramp: face (0, 1) lies `turned` above it, face (1, 2)
    // a face's turn less.
    const double turned = -w.shell->GetAngle();
    const double face_turn = 2.0 * geom::kPi / w.scene.shell.sides;
    const double delta = std::clamp(target_rad - lean_rad, -0.9 * (face_turn - turned), 0.9 * turned);
    turn_all_about(w, pivot, delta);
    return delta * 180.0 / geom::kPi;
}

// The tipped release: the pile settled with the shell flat on its face; shell and pile turn
// together, as one rigid body, about the downhill vertex into the vertex release's pose. The pile's
// surface then leans by the turn against the horizontal, as a box filled on the table and stood on
// its edge: the grains start to flow only when the hand lets go.
void tip_onto_vertex(SimWorld& w) {
    const EngineUnits& u = w.units;
    const double delta = release_pose(w.scene, w.shell_props).angle_rad - static_cast<double>(w.shell->GetAngle());
    const geom::Vec2 v1 = w.outer_local_m[1];
    const b2Vec2 pivot = w.shell->GetWorldPoint(to_b2(v1, u));
    turn_all_about(w, pivot, delta);
    // Turned about the sharp vertex, a rounded one stands above the ramp: down onto its arc.
    const b2Vec2 sink = {0.0f, -static_cast<float>(u.to_units(rounding_drop_m(w, w.shell->GetAngle())))};
    for (b2Body* b : w.grains) b->SetTransform(b->GetPosition() + sink, b->GetAngle());
    w.shell->SetTransform(w.shell->GetPosition() + sink, w.shell->GetAngle());
}

}  // namespace

void pour_grains(SimWorld& w, const ShellPose& pose) {
    const Scene& scene = w.scene;
    const EngineUnits& u = w.units;
    const double theta = ramp_angle_rad(w);
    const Vec2 up_world = {-std::sin(theta), std::cos(theta)};
    w.fill = plan_fill(scene, w.shell_props, geom::rotate(up_world, -pose.angle_rad));
    for (const PlannedGrain& pg : w.fill.grains) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.userData.pointer = static_cast<uintptr_t>(BodyKind::grain);
        def.position = to_b2(pose.centre_m + geom::rotate(pg.position_m, pose.angle_rad), u) +
                       b2Vec2(0.0f, 2.0f * b2_polygonRadius);
        b2Body* body = w.world->CreateBody(&def);
        b2CircleShape circle;
        circle.m_radius = static_cast<float>(u.to_units(pg.radius_m));
        b2FixtureDef fd;
        fd.shape = &circle;
        // Box2D density is mass per engine area: this gives each grain its planned mass.
        const double area_units = geom::kPi * circle.m_radius * circle.m_radius;
        fd.density = static_cast<float>(pg.mass_kg / area_units);
        fd.friction = static_cast<float>(disc_friction(scene));
        fd.restitution = static_cast<float>(disc_restitution(scene));
        body->CreateFixture(&fd);
        w.grains.push_back(body);
    }
}

void settle_grains(SimWorld& w) {
    const Scene& scene = w.scene;
    if (w.grains.empty()) {
        // A fill too small for one grain was still held on its face (pour_pose): tip it.
        if (scene.release.pose == ReleasePose::tipped && scene.fill.ratio > 0.0) tip_onto_vertex(w);
        return;
    }
    const double dt = 1.0 / scene.fidelity.step_hz;
    const double rest_units = w.units.to_units(scene.run.rest_speed_m_s);
    const int max_steps = static_cast<int>(std::ceil(scene.run.settle_time_s * scene.fidelity.step_hz));
    const int min_steps = std::min(max_steps, static_cast<int>(std::ceil(0.05 * scene.fidelity.step_hz)));
    w.settled = false;
    int steps = 0;
    while (steps < max_steps) {
        w.step();
        ++steps;
        // A big pile settles for as long as it rolls: a caller's stop (a Ctrl-C in Python) is heard here too.
        if (run_stop_requested()) throw RunStopped("the run was stopped while its grains settled");
        if (steps < min_steps) continue;
        float fastest = 0.0f;
        for (const b2Body* b : w.grains) fastest = std::max(fastest, b->GetLinearVelocity().Length());
        if (fastest < rest_units) {
            w.settled = true;
            break;
        }
    }
    w.settle_time_s = steps * dt;
    for (b2Body* b : w.grains) {
        b->SetLinearVelocity(b2Vec2_zero);
        b->SetAngularVelocity(0.0f);
    }
    if (scene.release.pose == ReleasePose::tipped) tip_onto_vertex(w);
    const double theta = ramp_angle_rad(w);
    if (released_on_vertex(scene.release) && theta < geom::kPi / w.shell_props.sides)
        w.balance_correction_deg = balance_on_pivot(w, theta);
}

}  // namespace polyroll::world_parts
