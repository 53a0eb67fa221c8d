// The tracker: see tracker.h.
#include "sim/tracker.h"

#include <cmath>

#include <fmt/format.h>

#include "sim/ramp_profile.h"
#include "sim/sample_clock.h"

namespace polyroll {

void set_terminal_velocity(Measurements& m, int sides) {
    const auto& imp = m.impacts;
    if (imp.size() < 2) return;
    const size_t last = imp.size() - 1;
    const size_t first = last >= static_cast<size_t>(sides) ? last - static_cast<size_t>(sides) : 0;
    m.terminal_velocity_m_s = (imp[last].position_m - imp[first].position_m) / (imp[last].time_s - imp[first].time_s);
    m.terminal_velocity_faces = static_cast<int>(last - first);
}

void record_delayed_kinetic(Measurements& m, double time_s, double step_s, double kinetic_J) {
    // Newest first, and only impacts whose delay ends within this step: older ones were read at their
    // own step, or came from a model without such a reading (a hand-over) and stay without one.
    for (auto it = m.impacts.rbegin(); it != m.impacts.rend(); ++it) {
        const double due_s = it->time_s + kKineticDelay_s - 1e-9;
        if (due_s < time_s - step_s) break;
        if (time_s >= due_s && !it->kinetic_delayed_J) it->kinetic_delayed_J = kinetic_J;
    }
}

void set_terminal_velocity_at_end(Measurements& m, int sides, const TrajectorySample& end) {
    set_terminal_velocity(m, sides);
    if (m.terminal_velocity_m_s) return;
    const double t0 = 0.9 * end.time_s;
    for (const TrajectorySample& s : m.trajectory) {
        if (s.time_s >= t0 && s.time_s < end.time_s) {
            m.terminal_velocity_m_s = (end.position_m - s.position_m) / (end.time_s - s.time_s);
            return;
        }
    }
}

std::string to_string(Behaviour b) {
    switch (b) {
        case Behaviour::running: return "running";
        case Behaviour::stopped_at_first_impact: return "stopped_at_first_impact";
        case Behaviour::stopped: return "stopped";
        case Behaviour::rolled_to_end: return "rolled_to_end";
        case Behaviour::time_limit: return "time_limit";
        case Behaviour::diverged: return "diverged";
    }
    return "unknown";
}

namespace {
// A landing vertex closer to the ramp than this counts as touching it. Box2D keeps shapes about two
// skins (0.02 engine units) apart; 0.05 units leaves room for that and for the linear slop.
constexpr double kContactToleranceUnits = 0.05;
// A touching vertex still approaching faster than this share of the centre's speed has not been
// stopped by the impact yet (its approach speed is about sin(2 pi/n) of the centre's, 0.1 at n = 64).
constexpr double kApproachShare = 0.02;
// Energy may not rise above its release value by more than this share of (total mass x g x pivot
// radius) before the run is declared diverged; physical runs only lose energy.
constexpr double kDivergedEnergyShare = 0.5;
// Share of the engine's speed cap (2 units per engine step) at which a run is declared diverged.
constexpr double kSpeedCapShare = 0.8;
}  // namespace

Tracker::Tracker(const SimWorld& w) : w_(w) {
    upm_ = w.units.units_per_m;
    double total_mass = w.shell_props.mass_kg;
    for (const PlannedGrain& g : w.fill.grains) total_mass += g.mass_kg;
    energy_scale_J_ = total_mass * w.scene.run.gravity_m_s2 * w.shell_props.pivot_radius_m;
    speed_cap_m_s_ = w.units.speed_cap_m_s(w.scene.fidelity);
    contact_tol_m_ = kContactToleranceUnits / upm_;
    step_dt_s_ = 1.0 / w.scene.fidelity.step_hz;
    m_.grains_inside = static_cast<int>(w.grains.size());
    start_angle_rad_ = w.shell->GetAngle();
    potential_at_release_J_ = sample(0.0).potential_J;
}

void Tracker::continue_from(const HandOver& from) {
    m_ = from.measured;
    m_.behaviour = Behaviour::running;
    m_.grains_inside = static_cast<int>(w_.grains.size());
    start_angle_rad_ = from.release.angle_rad;
    landed_vertex_ = from.landed_vertex;
    samples_taken_ = static_cast<long>(m_.trajectory.size());
    next_sample_step_ = first_step_at(samples_taken_, w_.scene.fidelity.step_hz, w_.scene.run.sample_hz);
    // The potential is booked from the release the first model saw: offset so that it reads now what
    // that model read (the fill's mass may be spread differently in the two models).
    const double t = static_cast<double>(from.steps) * step_dt_s_;
    potential_at_release_J_ = 0.0;
    potential_at_release_J_ = sample(t).potential_J - from.potential_J;
    now_ = sample(t);
    previous_kinetic_J_ = now_.kinetic_J;
}

TrajectorySample Tracker::sample(double time_s) const {
    TrajectorySample s;
    s.time_s = time_s;
    const b2Body* shell = w_.shell;
    s.position_m = shell->GetPosition().x / upm_ - w_.start_centre_x_m;
    s.speed_m_s = shell->GetLinearVelocity().x / upm_;
    s.angle_deg = -(shell->GetAngle() - start_angle_rad_) * 180.0 / geom::kPi;
    double kinetic_u = 0.0, potential_u = 0.0;
    const b2Vec2 g = w_.world->GetGravity();
    const RampParams& ramp = w_.scene.ramp;
    const bool curved = ramp_is_curved(ramp);
    // On a curved track gravity turns with the shell, so the potential is the track's (ramp_profile.h),
    // in engine units like the straight track's -m g.p.
    const double g_units = w_.scene.run.gravity_m_s2 * upm_;
    auto add = [&](const b2Body* b) {
        const b2Vec2 v = b->GetLinearVelocity();
        const double omega = b->GetAngularVelocity();
        kinetic_u += 0.5 * b->GetMass() * (double(v.x) * v.x + double(v.y) * v.y) + 0.5 * b->GetInertia() * omega * omega;
        const b2Vec2 p = b->GetWorldCenter();
        if (curved)
            potential_u += b->GetMass() * g_units * upm_ * height_m(ramp, p.x / upm_, p.y / upm_);
        else
            potential_u -= b->GetMass() * (double(g.x) * p.x + double(g.y) * p.y);
    };
    add(shell);
    double fill_mass_kg = 0.0, fill_x_u = 0.0, fill_y_u = 0.0;
    for (const b2Body* b : w_.grains) {
        add(b);
        const b2Vec2 p = b->GetWorldCenter();
        fill_mass_kg += b->GetMass();
        fill_x_u += b->GetMass() * double(p.x);
        fill_y_u += b->GetMass() * double(p.y);
    }
    if (fill_mass_kg > 0.0) {
        const b2Vec2 c = shell->GetPosition();
        s.fill_ahead_m = (fill_x_u / fill_mass_kg - c.x) / upm_;
        s.fill_up_m = (fill_y_u / fill_mass_kg - c.y) / upm_;
    }
    s.kinetic_J = kinetic_u / (upm_ * upm_);
    s.potential_J = potential_u / (upm_ * upm_) - potential_at_release_J_;
    s.dissipated_J = -(s.kinetic_J + s.potential_J);
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

void Tracker::finish(Behaviour b, double time_s) {
    m_.behaviour = b;
    m_.end_time_s = time_s;
    m_.distance_m = now_.position_m;
    if (b != Behaviour::diverged) m_.grains_inside = count_grains_inside();
    // The last state is always in the trajectory, so the file ends where the run ended.
    if (m_.trajectory.empty() || m_.trajectory.back().time_s < time_s) m_.trajectory.push_back(now_);
    if (b == Behaviour::rolled_to_end) set_terminal_velocity_at_end(m_, w_.scene.shell.sides, now_);
}

void Tracker::diverge(const std::string& why, double time_s) {
    m_.behaviour = Behaviour::diverged;
    m_.divergence = fmt::format("at t = {:.4f} s: {}", time_s, why);
    m_.end_time_s = time_s;
    m_.distance_m = m_.trajectory.empty() ? 0.0 : m_.trajectory.back().position_m;
    m_.grains_inside = count_grains_inside();
}

void Tracker::check_impact(double time_s, double kinetic_J) {
    const int n = w_.scene.shell.sides;
    const double a = w_.shell->GetAngle();
    // The lowest vertex, unwrapped: vertex j points straight down when a = pi/n - 2 pi j/n, so
    // j = 1/2 - a n / (2 pi). Vertex 1 is the pivot at release.
    const long lowest = static_cast<long>(std::floor(1.0 - a * n / (2.0 * geom::kPi)));
    if (lowest <= landed_vertex_) {
        impact_pending_ = false;
        return;
    }
    const int j = static_cast<int>(((lowest % n) + n) % n);
    const geom::Vec2 v_local = w_.outer_local_m[static_cast<size_t>(j)];
    const b2Vec2 v_world = w_.shell->GetWorldPoint(b2Vec2(static_cast<float>(v_local.x * upm_),
                                                          static_cast<float>(v_local.y * upm_)));
    const double height_m = v_world.y / upm_;
    if (height_m >= contact_tol_m_) {
        impact_pending_ = false;
        return;
    }
    const double normal_speed = w_.shell->GetLinearVelocityFromWorldPoint(v_world).y / upm_;
    const double threshold = std::max(kApproachShare * std::fabs(now_.speed_m_s), 0.1 * w_.scene.run.rest_speed_m_s);
    if (normal_speed < -threshold) {
        // Touching but not yet stopped: the impact happens in a later step.
        impact_pending_ = true;
        kinetic_before_J_ = kinetic_J;
        return;
    }
    FaceImpact f;
    f.index = static_cast<int>(m_.impacts.size()) + 1;
    f.time_s = time_s;
    f.position_m = now_.position_m;
    f.kinetic_before_J = impact_pending_ ? kinetic_before_J_ : previous_kinetic_J_;
    f.kinetic_after_J = kinetic_J;
    m_.impacts.push_back(f);
    landed_vertex_ = lowest;
    impact_pending_ = false;
}

bool Tracker::check_grains(double time_s) {
    for (const b2Body* b : w_.grains) {
        const b2Vec2 p = b->GetPosition(), v = b->GetLinearVelocity();
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(v.x) || !std::isfinite(v.y)) {
            diverge("a grain's position or velocity is not a finite number", time_s);
            return false;
        }
        if (v.Length() / upm_ > kSpeedCapShare * speed_cap_m_s_) {
            diverge(fmt::format("a grain moves at {:.2f} m/s, near the engine's limit of {:.2f} m/s for this "
                                "time step; use a finer fidelity (more substeps)",
                                v.Length() / upm_, speed_cap_m_s_),
                    time_s);
            return false;
        }
    }
    const int inside = count_grains_inside();
    m_.grains_inside = inside;
    if (inside < static_cast<int>(w_.grains.size())) {
        diverge(fmt::format("{} of {} grains left the shell through its walls{}; use a finer fidelity",
                            static_cast<int>(w_.grains.size()) - inside, w_.grains.size(),
                            time_s == 0.0 ? " while they settled before release" : ""),
                time_s);
        return false;
    }
    return true;
}

bool Tracker::observe(long step) {
    if (m_.behaviour != Behaviour::running) return false;
    const double t = step * step_dt_s_;
    const b2Body* shell = w_.shell;
    const b2Vec2 p = shell->GetPosition(), v = shell->GetLinearVelocity();
    const float omega = shell->GetAngularVelocity();
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(v.x) || !std::isfinite(v.y) ||
        !std::isfinite(omega) || !std::isfinite(shell->GetAngle())) {
        diverge("the shell's position or velocity is not a finite number", t);
        return false;
    }
    now_ = sample(t);
    const double speed_m_s = v.Length() / upm_;
    if (speed_m_s > kSpeedCapShare * speed_cap_m_s_) {
        diverge(fmt::format("the shell moves at {:.2f} m/s, near the engine's limit of {:.2f} m/s for this time "
                            "step; use a finer fidelity (more substeps)",
                            speed_m_s, speed_cap_m_s_),
                t);
        return false;
    }
    const double gain = -now_.dissipated_J;
    m_.max_energy_gain_J = std::max(m_.max_energy_gain_J, gain);
    if (gain > kDivergedEnergyShare * energy_scale_J_) {
        diverge(fmt::format("the total energy rose {:.3g} J above its value at release (physical runs only "
                            "lose energy); use a finer fidelity",
                            gain),
                t);
        return false;
    }

    if (step > 0) check_impact(t, now_.kinetic_J);
    previous_kinetic_J_ = now_.kinetic_J;
    record_delayed_kinetic(m_, t, step_dt_s_, now_.kinetic_J);

    if (step >= next_sample_step_) {
        m_.trajectory.push_back(now_);
        ++samples_taken_;
        next_sample_step_ = first_step_at(samples_taken_, w_.scene.fidelity.step_hz, w_.scene.run.sample_hz);
        if (!w_.grains.empty() && !check_grains(t)) return false;
    }

    // Rest: the lid centre and the rim both slower than the rest speed, for the rest time.
    const double rim_speed = std::fabs(omega) * w_.shell_props.pivot_radius_m;
    if (speed_m_s < w_.scene.run.rest_speed_m_s && rim_speed < w_.scene.run.rest_speed_m_s) {
        if (rest_since_s_ < 0.0) rest_since_s_ = t;
        if (t - rest_since_s_ >= w_.scene.run.rest_time_s) {
            m_.stop_time_s = rest_since_s_;
            finish(m_.impacts.size() <= 1 ? Behaviour::stopped_at_first_impact : Behaviour::stopped, t);
            return false;
        }
    } else {
        rest_since_s_ = -1.0;
    }
    if (p.x / upm_ >= w_.end_centre_x_m) {
        finish(Behaviour::rolled_to_end, t);
        return false;
    }
    if (t >= w_.scene.run.time_limit_s - 0.5 * step_dt_s_) {
        finish(Behaviour::time_limit, t);
        return false;
    }
    return true;
}

}  // namespace polyroll
