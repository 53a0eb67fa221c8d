// Lid friction: see lid_friction.h.
#include "sim/grains/lid_friction.h"

#include <algorithm>
#include <cmath>

namespace polyroll {

double lateral_pressure_ratio(double grain_friction) {
    return 1.0 - std::sin(std::atan(grain_friction));
}

double lid_normal_force_n(double grain_mass_kg, double gravity_m_s2, double depth_below_top_m, double shell_depth_m,
                          double lateral_ratio) {
    // The column of grains a disc stands for weighs m g and has its two ends on the lids; the
    // vertical stress at depth h is (bulk density) g h, the lateral one K times that, on an end of
    // the column's cross-section A: 2 K (rho g h) A = m g (2 K h / depth), as m = rho A depth.
    // No Janssen saturation: the piles here are at most a few centimetres deep, less than the
    // depth between the lids, where the wall friction would begin to carry the weight.
    return grain_mass_kg * gravity_m_s2 * 2.0 * lateral_ratio * depth_below_top_m / shell_depth_m;
}

void apply_lid_friction(SimWorld& w, double engine_step_s) {
    const MaterialParams& m = w.scene.fill.material;
    if (m.lid_friction <= 0.0 || w.grains.empty()) return;
    const EngineUnits& u = w.units;
    const double g_m_s2 = std::hypot(w.gravity_m_s2.x, w.gravity_m_s2.y);
    const b2Vec2 down = {static_cast<float>(w.gravity_m_s2.x / g_m_s2), static_cast<float>(w.gravity_m_s2.y / g_m_s2)};

    // The top of the pile: the highest grain's top, along gravity.
    double top_units = -1e30;
    for (const b2Body* b : w.grains) {
        const double r = b->GetFixtureList()->GetShape()->m_radius;
        top_units = std::max(top_units, -b2Dot(down, b->GetPosition()) + r);
    }

    const double k = lateral_pressure_ratio(m.friction);
    b2Body* shell = w.shell;
    const bool shell_moves = shell->GetType() == b2_dynamicBody;
    const b2Vec2 c = shell->GetWorldCenter();
    const b2Vec2 v_shell = shell->GetLinearVelocity();
    const double omega = shell->GetAngularVelocity();
    const double inv_mass_shell = shell_moves ? 1.0 / shell->GetMass() : 0.0;
    const double inv_inertia_shell = shell_moves ? 1.0 / shell->GetInertia() : 0.0;  // about the centre of mass

    for (b2Body* b : w.grains) {
        const b2Vec2 p = b->GetPosition();
        const b2Vec2 r = p - c;
        // The grain's velocity relative to the shell's material at the grain.
        const b2Vec2 v_here = v_shell + b2Vec2(static_cast<float>(-omega * r.y), static_cast<float>(omega * r.x));
        const b2Vec2 v_rel = b->GetLinearVelocity() - v_here;
        const double speed_units = v_rel.Length();
        if (speed_units <= 0.0) continue;
        const double ux = v_rel.x / speed_units, uy = v_rel.y / speed_units;

        const double depth_m = u.to_m(std::max(0.0, top_units - -b2Dot(down, p)));
        const double grain_mass_kg = b->GetMass();
        const double friction_n = m.lid_friction * lid_normal_force_n(grain_mass_kg, g_m_s2, depth_m,
                                                                      w.scene.shell.depth_m, k);
        // Kinetic friction for this step, but never more than stops the relative sliding: the
        // impulse that brings it to zero, through the pair's effective mass along the sliding.
        const double r_cross_u = r.x * uy - r.y * ux;
        const double inv_eff_mass = 1.0 / grain_mass_kg + inv_mass_shell + r_cross_u * r_cross_u * inv_inertia_shell;
        const double impulse = std::min(u.to_units(friction_n) * engine_step_s, speed_units / inv_eff_mass);
        const b2Vec2 j = {static_cast<float>(impulse * ux), static_cast<float>(impulse * uy)};
        b->ApplyLinearImpulseToCenter(-j, false);
        if (shell_moves) shell->ApplyLinearImpulse(j, p, false);
    }
}

}  // namespace polyroll
