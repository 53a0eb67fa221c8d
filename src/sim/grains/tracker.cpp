// The grain simulation's tracker: see tracker.h.
#include "sim/grains/tracker.h"

#include <cmath>

#include <fmt/core.h>

#include "sim/geometry/ramp_profile.h"
#include "sim/geometry/vertex_rounding.h"
#include "sim/grains/world_parts.h"

namespace polyroll {

namespace {
// A landing vertex closer to the ramp than this counts as touching it. Box2D keeps shapes about two
// skins (0.02 engine units) apart; 0.05 units leaves room for that and for the linear slop. A
// rounded vertex (vertex_rounding.h) lands on its arc with the sharp corner that much higher again.
constexpr double kContactToleranceUnits = 0.05;
// Share of the engine's speed cap (2 units per engine step) at which a run is declared diverged.
constexpr double kSpeedCapShare = 0.8;

ShellPose box2d_release(const SimWorld& w) {
    ShellPose p;
    p.angle_rad = w.shell->GetAngle();
    p.centre_m = {w.start_centre_x_m, w.shell->GetPosition().y / w.units.units_per_m};
    return p;
}
}  // namespace

TrackRules box2d_track_rules(const SimWorld& w) {
    double total_mass_kg = w.shell_props.mass_kg;
    for (const PlannedGrain& g : w.fill.grains) total_mass_kg += g.mass_kg;
    TrackRules r;
    r.grains = static_cast<int>(w.grains.size());
    r.energy_scale_J = total_mass_kg * w.scene.run.gravity_m_s2 * w.shell_props.pivot_radius_m;
    ShellParams engine_shell = w.scene.shell;
    engine_shell.vertex_radius_m = world_parts::engine_vertex_radius_m(w);
    r.contact_tolerance_m = kContactToleranceUnits / w.units.units_per_m + vertex_rounding_lift_max_m(engine_shell);
    r.grains_leave_through = "the shell through its walls";
    r.remedy = "use a finer fidelity";
    return r;
}

Tracker::Tracker(const SimWorld& w)
    : w_(w), rules_(w.scene, box2d_release(w), box2d_track_rules(w), [this] { return check_grains(); }) {
    upm_ = w.units.units_per_m;
    speed_cap_m_s_ = w.units.speed_cap_m_s(w.scene.fidelity);
    step_dt_s_ = 1.0 / w.scene.fidelity.step_hz;
    potential_at_release_J_ = observe_world(0.0).potential_J;
}

void Tracker::continue_from(const HandOver& from) {
    // The potential is booked from the release the first model saw: offset so that it reads now what
    // that model read (the fill's mass may be spread differently in the two models).
    const double t = static_cast<double>(from.steps) * step_dt_s_;
    potential_at_release_J_ = 0.0;
    potential_at_release_J_ = observe_world(t).potential_J - from.potential_J;
    observed_ = observe_world(t);
    rules_.continue_from(from, observed_);
}

ObservedState Tracker::observe_world(double time_s) const {
    ObservedState s;
    s.time_s = time_s;
    const b2Body* shell = w_.shell;
    const b2Vec2 p = shell->GetPosition(), v = shell->GetLinearVelocity();
    s.shell.pose.centre_m = {p.x / upm_, p.y / upm_};
    s.shell.pose.angle_rad = shell->GetAngle();
    s.shell.velocity_m_s = {v.x / upm_, v.y / upm_};
    s.shell.angular_velocity_rad_s = shell->GetAngularVelocity();

    double kinetic_u = 0.0, potential_u = 0.0;
    const b2Vec2 g = w_.world->GetGravity();
    const RampParams& ramp = w_.scene.ramp;
    const bool curved = ramp_is_curved(ramp);
    // On a curved track gravity turns with the shell, so the potential is the track's (ramp_profile.h),
    // in engine units like the straight track's -m g.p.
    const double g_units = w_.scene.run.gravity_m_s2 * upm_;
    auto add = [&](const b2Body* b) {
        const b2Vec2 bv = b->GetLinearVelocity();
        const double omega = b->GetAngularVelocity();
        kinetic_u += 0.5 * b->GetMass() * (double(bv.x) * bv.x + double(bv.y) * bv.y) + 0.5 * b->GetInertia() * omega * omega;
        const b2Vec2 c = b->GetWorldCenter();
        if (curved)
            potential_u += b->GetMass() * g_units * upm_ * height_m(ramp, c.x / upm_, c.y / upm_);
        else
            potential_u -= b->GetMass() * (double(g.x) * c.x + double(g.y) * c.y);
    };
    add(shell);
    double fill_mass_kg = 0.0, fill_x_u = 0.0, fill_y_u = 0.0;
    for (const b2Body* b : w_.grains) {
        add(b);
        const b2Vec2 c = b->GetWorldCenter();
        fill_mass_kg += b->GetMass();
        fill_x_u += b->GetMass() * double(c.x);
        fill_y_u += b->GetMass() * double(c.y);
    }
    if (fill_mass_kg > 0.0)
        s.fill_offset_m = geom::Vec2{(fill_x_u / fill_mass_kg - p.x) / upm_, (fill_y_u / fill_mass_kg - p.y) / upm_};
    s.kinetic_J = kinetic_u / (upm_ * upm_);
    s.potential_J = potential_u / (upm_ * upm_) - potential_at_release_J_;
    return s;
}

int Tracker::count_grains_inside() const {
    int inside = 0;
    for (const b2Body* b : w_.grains) {
        const b2Vec2 local = w_.shell->GetLocalPoint(b->GetPosition());
        const geom::Vec2 p_m = {local.x / upm_, local.y / upm_};
        if (std::isfinite(p_m.x) && std::isfinite(p_m.y) && geom::inside_distance(w_.inner_local_m, p_m) >= 0.0)
            ++inside;
    }
    return inside;
}

GrainCheck Tracker::check_grains() const {
    GrainCheck c;
    for (const b2Body* b : w_.grains) {
        const b2Vec2 p = b->GetPosition(), v = b->GetLinearVelocity();
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(v.x) || !std::isfinite(v.y)) {
            c.trouble = "a grain's position or velocity is not a finite number";
            break;
        }
        if (v.Length() / upm_ > kSpeedCapShare * speed_cap_m_s_) {
            c.trouble = fmt::format("a grain moves at {:.2f} m/s, near the engine's limit of {:.2f} m/s for this "
                                    "time step; use a finer fidelity (more substeps)",
                                    v.Length() / upm_, speed_cap_m_s_);
            break;
        }
    }
    c.inside = count_grains_inside();
    return c;
}

bool Tracker::observe(long step) {
    if (!rules_.running()) return false;
    observed_ = observe_world(static_cast<double>(step) * step_dt_s_);
    const ShellState& shell = observed_.shell;
    const double speed_m_s = std::hypot(shell.velocity_m_s.x, shell.velocity_m_s.y);
    if (std::isfinite(speed_m_s) && speed_m_s > kSpeedCapShare * speed_cap_m_s_) {
        rules_.diverge(observed_, fmt::format("the shell moves at {:.2f} m/s, near the engine's limit of {:.2f} m/s "
                                              "for this time step; use a finer fidelity (more substeps)",
                                              speed_m_s, speed_cap_m_s_));
        return false;
    }
    return rules_.observe(step, observed_);
}

}  // namespace polyroll
