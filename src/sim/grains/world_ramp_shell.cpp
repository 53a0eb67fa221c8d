// The ramp and the shell, held and let go: see world_parts.h.
#include "sim/grains/world_parts.h"

#include <cmath>

#include "sim/geometry/vertex_rounding.h"

namespace polyroll::world_parts {

void add_ramp(SimWorld& w) {
    // Reaching past both ends so a polygon at the end still has a surface under it until the run
    // stops it.
    const Scene& scene = w.scene;
    const EngineUnits& u = w.units;
    b2BodyDef def;
    // In the pile's frame the ramp moves under the shell (moving_frame.h): a kinematic body, at the
    // origin so that the frame's shift puts it back exactly. Static otherwise, as without grains.
    const bool moves = scene.fidelity.frame == EngineFrame::pile && scene.fill.ratio > 0.0;
    def.type = moves ? b2_kinematicBody : b2_staticBody;
    def.userData.pointer = static_cast<uintptr_t>(BodyKind::ramp);
    w.ramp = w.world->CreateBody(&def);
    const double margin_m = 4.0 * w.shell_props.outer_circumradius_m;
    const double half_len_m = scene.ramp.length_m / 2.0 + margin_m;
    const double half_thick_m = 0.025;
    b2PolygonShape box;
    box.SetAsBox(static_cast<float>(u.to_units(half_len_m)), static_cast<float>(u.to_units(half_thick_m)),
                 to_b2({scene.ramp.length_m / 2.0, -half_thick_m}, u), 0.0f);
    b2FixtureDef fd;
    fd.shape = &box;
    fd.friction = static_cast<float>(scene.ramp.friction);
    fd.restitution = static_cast<float>(scene.ramp.restitution);
    w.ramp->CreateFixture(&fd);
}

double engine_vertex_radius_m(const SimWorld& w) {
    const double skin_m = w.units.to_m(b2_polygonRadius);
    return w.scene.shell.vertex_radius_m > skin_m ? w.scene.shell.vertex_radius_m : 0.0;
}

namespace {
// One fixture of the shell: the ramp's friction on it (Box2D mixes two fixtures' as sqrt(a b), and the
// shell's contact with the ramp is set by ContactMaterials anyway), no bounce.
void add_shell_part(SimWorld& w, const b2Shape& shape) {
    b2FixtureDef fd;
    fd.shape = &shape;
    fd.density = 1.0f;  // replaced by the real mass data on release
    fd.friction = static_cast<float>(w.scene.ramp.friction);
    fd.restitution = 0.0f;
    w.shell->CreateFixture(&fd);
}

// The shell as the engine holds it: the scene's, with the engine's vertex radius.
ShellParams engine_shell(const SimWorld& w) {
    ShellParams s = w.scene.shell;
    s.vertex_radius_m = engine_vertex_radius_m(w);
    return s;
}
}  // namespace

double rounding_drop_m(const SimWorld& w, double angle_rad) {
    return engine_vertex_radius_m(w) > 0.0 ? vertex_rounding_drop_m(engine_shell(w), angle_rad) : 0.0;
}

ShellPose rounded_pose(const SimWorld& w, ShellPose pose) {
    pose.centre_m.y -= rounding_drop_m(w, pose.angle_rad);
    return pose;
}

void add_shell(SimWorld& w, const ShellPose& pose) {
    // One trapezoid per side between the inner and outer polygons, so the corners are closed
    // (rectangles leave notches a squeezed pile leaks through).
    const EngineUnits& u = w.units;
    const double radius_m = engine_vertex_radius_m(w);
    b2BodyDef def;
    def.type = b2_staticBody;
    def.userData.pointer = static_cast<uintptr_t>(BodyKind::shell);
    // Lift by the two shapes' skins so the shell starts touching, not overlapping, the ramp.
    def.position = to_b2(pose.centre_m, u) + b2Vec2(0.0f, 2.0f * b2_polygonRadius);
    def.angle = static_cast<float>(pose.angle_rad);
    w.shell = w.world->CreateBody(&def);
    const int n = w.scene.shell.sides;
    // With rounded vertices each side's outer edge ends where the arcs meet it; the inner edge, which
    // the grains touch, is whole.
    const double cut_m = radius_m > 0.0 ? vertex_arc_tangent_m(n, radius_m) : 0.0;
    for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        const geom::Vec2 along = (1.0 / geom::length(w.outer_local_m[j] - w.outer_local_m[i])) *
                                 (w.outer_local_m[j] - w.outer_local_m[i]);
        b2Vec2 quad[4] = {to_b2(w.inner_local_m[i], u), to_b2(w.outer_local_m[i] + cut_m * along, u),
                          to_b2(w.outer_local_m[j] - cut_m * along, u), to_b2(w.inner_local_m[j], u)};
        b2PolygonShape shape;
        shape.Set(quad, 4);
        add_shell_part(w, shape);
    }
    if (radius_m <= 0.0) return;
    // The arcs: circles tangent to both faces' outer lines. A circle has no skin, so it is grown by
    // the polygons' own to stay flush with the faces beside it. Between two cut sides and the arc a
    // wedge from the inner corner would be left open, a gap a fast grain could slip into: a triangle
    // closes it, so the corner is as solid as a sharp one.
    for (int i = 0; i < n; ++i) {
        const geom::Vec2 v = w.outer_local_m[i];
        const geom::Vec2 before = w.outer_local_m[(i + n - 1) % n], after = w.outer_local_m[(i + 1) % n];
        b2Vec2 wedge[3] = {to_b2(w.inner_local_m[i], u), to_b2(v + (cut_m / geom::length(before - v)) * (before - v), u),
                           to_b2(v + (cut_m / geom::length(after - v)) * (after - v), u)};
        // Box2D welds points nearer than half its linear slop (and refuses the shape left); a wedge that
        // narrow leaves no gap a grain could find, so it is not needed (many sides, a small radius).
        if (b2Distance(wedge[1], wedge[2]) < 2.0f * b2_linearSlop) continue;
        b2PolygonShape shape;
        shape.Set(wedge, 3);
        add_shell_part(w, shape);
    }
    for (const geom::Vec2& c : vertex_arc_centres_m(engine_shell(w))) {
        b2CircleShape arc;
        arc.m_p = to_b2(c, u);
        arc.m_radius = static_cast<float>(u.to_units(radius_m)) + b2_polygonRadius;
        add_shell_part(w, arc);
    }
}

void release_shell(SimWorld& w, geom::Vec2 velocity_m_s, double angular_velocity_rad_s) {
    // SetType recomputes mass from the fixtures, so the mass data comes after it.
    const EngineUnits& u = w.units;
    w.shell->SetType(b2_dynamicBody);
    b2MassData md;
    md.mass = static_cast<float>(w.shell_props.mass_kg);
    md.center = b2Vec2_zero;
    md.I = static_cast<float>(w.shell_props.inertia_kg_m2 * u.units_per_m * u.units_per_m);
    w.shell->SetMassData(&md);
    w.shell->SetLinearVelocity(to_b2(velocity_m_s, u));
    w.shell->SetAngularVelocity(static_cast<float>(angular_velocity_rad_s));
    w.shell->SetAwake(true);
    for (b2Body* b : w.grains) b->SetAwake(true);
}

}  // namespace polyroll::world_parts
