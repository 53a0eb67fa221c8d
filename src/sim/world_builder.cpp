// Building and settling the Box2D world of a scene: see world_builder.h.
#include "sim/world_builder.h"

#include <algorithm>
#include <cmath>

namespace polyroll {

using geom::Vec2;

namespace {

BodyKind kind_of(b2Fixture* f) { return static_cast<BodyKind>(f->GetBody()->GetUserData().pointer); }

b2Vec2 to_b2(Vec2 v_m, const EngineUnits& u) {
    return {static_cast<float>(u.to_units(v_m.x)), static_cast<float>(u.to_units(v_m.y))};
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
    const b2Vec2 pivot = w.shell->GetWorldPoint(b2Vec2(static_cast<float>(u.to_units(v1.x)),
                                                       static_cast<float>(u.to_units(v1.y))));
    const geom::Vec2 lean = {mx / mass - pivot.x, my / mass - pivot.y};
    const geom::Vec2 up = {-std::sin(theta), std::cos(theta)};
    const double lean_rad = std::atan2(geom::cross(up, lean), geom::dot(up, lean));  // + is uphill
    const double target_rad = -w.scene.release.tilt_deg * geom::kPi / 180.0;
    // Keep both neighbouring faces off the ramp: face (0, 1) lies `turned` above it, face (1, 2)
    // a face's turn less.
    const double turned = -w.shell->GetAngle();
    const double face_turn = 2.0 * geom::kPi / w.scene.shell.sides;
    const double delta = std::clamp(target_rad - lean_rad, -0.9 * (face_turn - turned), 0.9 * turned);
    auto turn = [&](b2Body* b) {
        const b2Vec2 rel = b->GetPosition() - pivot;
        const geom::Vec2 r = geom::rotate({rel.x, rel.y}, delta);
        b->SetTransform(pivot + b2Vec2(static_cast<float>(r.x), static_cast<float>(r.y)),
                        b->GetAngle() + static_cast<float>(delta));
    };
    turn(w.shell);
    for (b2Body* b : w.grains) turn(b);
    return delta * 180.0 / geom::kPi;
}

}  // namespace

void ContactMaterials::BeginContact(b2Contact* contact) {
    const BodyKind a = kind_of(contact->GetFixtureA()), b = kind_of(contact->GetFixtureB());
    auto is = [&](BodyKind x, BodyKind y) { return (a == x && b == y) || (a == y && b == x); };
    if (is(BodyKind::shell, BodyKind::ramp)) {
        contact->SetFriction(static_cast<float>(scene_.ramp.friction));
        contact->SetRestitution(static_cast<float>(scene_.ramp.restitution));
    } else if (is(BodyKind::grain, BodyKind::shell)) {
        contact->SetFriction(static_cast<float>(scene_.fill.material.wall_friction));
        contact->SetRestitution(static_cast<float>(scene_.fill.material.restitution));
    }
    // Grain on grain: both fixtures carry the material's values, which Box2D's mixing keeps.
}

void SimWorld::step() {
    const float dt = static_cast<float>(1.0 / (scene.fidelity.step_hz * scene.fidelity.substeps));
    for (int i = 0; i < scene.fidelity.substeps; ++i)
        world->Step(dt, scene.fidelity.velocity_iterations, scene.fidelity.position_iterations);
}

Pose release_pose(const Scene& scene, const ShellProperties& p) {
    const double theta = scene.ramp.angle_deg * geom::kPi / 180.0;
    const double n = p.sides;
    // Resting on face (0, 1): the face spans x = 0 .. side, vertex 1 (downhill) at x = side.
    const Vec2 pivot = {p.outer_side_m, 0.0};
    const Vec2 centre_from_pivot = {-p.outer_side_m / 2.0, p.outer_apothem_m};
    double rotation = 0.0;  // clockwise, about the pivot
    if (scene.release.pose == ReleasePose::vertex) {
        // Turn about the downhill vertex until the centre is straight above it (the line from
        // pivot to centre leans pi/n uphill of the ramp normal, the vertical theta), then past it
        // by the tilt. Steeper than pi/n the polygon tips from its face anyway: tilt alone.
        rotation = std::max(0.0, geom::kPi / n - theta) + scene.release.tilt_deg * geom::kPi / 180.0;
    } else {
        rotation = scene.release.tilt_deg * geom::kPi / 180.0;
    }
    Pose pose;
    pose.angle_rad = -rotation;
    pose.centre_m = pivot + geom::rotate(centre_from_pivot, -rotation);
    return pose;
}

std::unique_ptr<SimWorld> build_world(const Scene& scene) {
    auto w = std::make_unique<SimWorld>();
    w->scene = scene;
    w->units = choose_engine_units(scene);
    const EngineUnits& u = w->units;
    w->shell_props = shell_properties(scene.shell);
    const ShellProperties& sp = w->shell_props;
    w->outer_local_m = shell_outer_polygon_m(scene.shell);
    w->inner_local_m = shell_inner_polygon_m(scene.shell);

    const double theta = scene.ramp.angle_deg * geom::kPi / 180.0;
    const double g = scene.run.gravity_m_s2;
    w->gravity_m_s2 = {g * std::sin(theta), -g * std::cos(theta)};

    w->materials = std::make_unique<ContactMaterials>(w->scene);
    w->world = std::make_unique<b2World>(to_b2(w->gravity_m_s2, u));
    w->world->SetContactListener(w->materials.get());
    w->world->SetAllowSleeping(true);
    // Continuous collision in Box2D 2.4 only guards dynamic-vs-static pairs, here the shell on the
    // ramp. The ramp is 5 cm thick and the tracker stops any run whose shell nears 1.6 engine
    // units (at most 1.6 cm) per step, so the shell cannot pass through it; the
    // time-of-impact sub-steps cost about 10% of the default scene and, measured, moved the
    // rigid-impact energy ratios of empty shells further from the model (0.7-1.0% against 0.2-0.7%).
    w->world->SetContinuousPhysics(false);

    // Ramp: a thick static box whose top face is y = 0, reaching past both ends so a polygon at
    // the end still has a surface under it until the run stops it.
    {
        b2BodyDef def;
        def.type = b2_staticBody;
        def.userData.pointer = static_cast<uintptr_t>(BodyKind::ramp);
        w->ramp = w->world->CreateBody(&def);
        const double margin_m = 4.0 * sp.outer_circumradius_m;
        const double half_len_m = scene.ramp.length_m / 2.0 + margin_m;
        const double half_thick_m = 0.025;
        b2PolygonShape box;
        box.SetAsBox(static_cast<float>(u.to_units(half_len_m)), static_cast<float>(u.to_units(half_thick_m)),
                     to_b2({scene.ramp.length_m / 2.0, -half_thick_m}, u), 0.0f);
        b2FixtureDef fd;
        fd.shape = &box;
        fd.friction = static_cast<float>(scene.ramp.friction);
        fd.restitution = static_cast<float>(scene.ramp.restitution);
        w->ramp->CreateFixture(&fd);
    }

    const Pose pose = release_pose(scene, sp);
    w->start_centre_x_m = pose.centre_m.x;
    // The run ends when the front of the polygon reaches the ramp's end.
    w->end_centre_x_m = scene.ramp.length_m - sp.outer_circumradius_m;

    // Shell: one trapezoid per side between the inner and outer polygons, so the corners are closed
    // (rectangles leave notches a squeezed pile leaks through). Held static while the grains settle.
    {
        b2BodyDef def;
        def.type = b2_staticBody;
        def.userData.pointer = static_cast<uintptr_t>(BodyKind::shell);
        // Lift by the two shapes' skins so the shell starts touching, not overlapping, the ramp.
        def.position = to_b2(pose.centre_m, u) + b2Vec2(0.0f, 2.0f * b2_polygonRadius);
        def.angle = static_cast<float>(pose.angle_rad);
        w->shell = w->world->CreateBody(&def);
        const int n = scene.shell.sides;
        for (int i = 0; i < n; ++i) {
            const int j = (i + 1) % n;
            b2Vec2 quad[4] = {to_b2(w->inner_local_m[i], u), to_b2(w->outer_local_m[i], u),
                              to_b2(w->outer_local_m[j], u), to_b2(w->inner_local_m[j], u)};
            b2PolygonShape shape;
            shape.Set(quad, 4);
            b2FixtureDef fd;
            fd.shape = &shape;
            fd.density = 1.0f;  // replaced by the real mass data below
            fd.friction = static_cast<float>(scene.ramp.friction);
            fd.restitution = 0.0f;
            w->shell->CreateFixture(&fd);
        }
    }

    // Grains, planned in the shell's frame with gravity as seen from the release pose.
    const Vec2 up_world = {-std::sin(theta), std::cos(theta)};
    w->fill = plan_fill(scene, sp, geom::rotate(up_world, -pose.angle_rad));
    for (const PlannedGrain& pg : w->fill.grains) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.userData.pointer = static_cast<uintptr_t>(BodyKind::grain);
        def.position = to_b2(pose.centre_m + geom::rotate(pg.position_m, pose.angle_rad), u) +
                       b2Vec2(0.0f, 2.0f * b2_polygonRadius);
        b2Body* body = w->world->CreateBody(&def);
        b2CircleShape circle;
        circle.m_radius = static_cast<float>(u.to_units(pg.radius_m));
        b2FixtureDef fd;
        fd.shape = &circle;
        // Box2D density is mass per engine area: this gives each grain its planned mass.
        const double area_units = geom::kPi * circle.m_radius * circle.m_radius;
        fd.density = static_cast<float>(pg.mass_kg / area_units);
        fd.friction = static_cast<float>(scene.fill.material.friction);
        fd.restitution = static_cast<float>(scene.fill.material.restitution);
        body->CreateFixture(&fd);
        w->grains.push_back(body);
    }

    // Settle: the hand holds the polygon while the pile comes to rest with a level surface.
    if (!w->grains.empty()) {
        const double dt = 1.0 / scene.fidelity.step_hz;
        const double rest_units = u.to_units(scene.run.rest_speed_m_s);
        const int max_steps = static_cast<int>(std::ceil(scene.run.settle_time_s * scene.fidelity.step_hz));
        const int min_steps = std::min(max_steps, static_cast<int>(std::ceil(0.05 * scene.fidelity.step_hz)));
        w->settled = false;
        int steps = 0;
        while (steps < max_steps) {
            w->step();
            ++steps;
            if (steps < min_steps) continue;
            float fastest = 0.0f;
            for (const b2Body* b : w->grains) fastest = std::max(fastest, b->GetLinearVelocity().Length());
            if (fastest < rest_units) {
                w->settled = true;
                break;
            }
        }
        w->settle_time_s = steps * dt;
        for (b2Body* b : w->grains) {
            b->SetLinearVelocity(b2Vec2_zero);
            b->SetAngularVelocity(0.0f);
        }
        if (scene.release.pose == ReleasePose::vertex && theta < geom::kPi / sp.sides)
            w->balance_correction_deg = balance_on_pivot(*w, theta);
    }

    // Let go: the shell becomes dynamic with the real box's mass and moment of inertia about its
    // centre (SetType recomputes mass from the fixtures, so the mass data comes after it).
    w->shell->SetType(b2_dynamicBody);
    b2MassData md;
    md.mass = static_cast<float>(sp.mass_kg);
    md.center = b2Vec2_zero;
    md.I = static_cast<float>(sp.inertia_kg_m2 * u.units_per_m * u.units_per_m);
    w->shell->SetMassData(&md);
    w->shell->SetLinearVelocity(b2Vec2_zero);
    w->shell->SetAngularVelocity(0.0f);
    w->shell->SetAwake(true);
    for (b2Body* b : w->grains) b->SetAwake(true);
    // Measure from where the engine holds the shell (floats), so the first row reads exactly 0.
    w->start_centre_x_m = u.to_m(w->shell->GetPosition().x);
    return w;
}

}  // namespace polyroll
