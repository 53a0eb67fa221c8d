// The measurement rules: see shell_tracker.h.
#include "sim/shell_tracker.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/core.h>

#include "sim/geometry/shell_outline.h"
#include "sim/sample_clock.h"
#include "sim/geometry/shell_properties.h"

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

TrajectorySample trajectory_sample(const ObservedState& s, const ShellPose& release) {
    TrajectorySample t;
    t.time_s = s.time_s;
    t.position_m = s.shell.pose.centre_m.x - release.centre_m.x;
    t.speed_m_s = s.shell.velocity_m_s.x;
    t.angle_deg = -(s.shell.pose.angle_rad - release.angle_rad) * 180.0 / geom::kPi;
    t.kinetic_J = s.kinetic_J;
    t.potential_J = s.potential_J;
    t.dissipated_J = -(s.kinetic_J + s.potential_J);
    if (s.fill_offset_m) {
        t.fill_ahead_m = s.fill_offset_m->x;
        t.fill_up_m = s.fill_offset_m->y;
    }
    return t;
}

namespace {

// A touching vertex still approaching faster than this share of the centre's speed has not been
// stopped by the impact yet (its approach speed is about sin(2 pi/n) of the centre's, 0.1 at n = 64).
constexpr double kApproachShare = 0.02;
// Energy may not rise above its release value by more than this share of the energy scale before the
// run is declared diverged; physical runs only lose energy.
constexpr double kDivergedEnergyShare = 0.5;
// The rest window is held when the time since rest began reaches the rest time within this: times
// read back from a file (the 3D reference's rows) carry rounding, and a window of exactly the rest
// time must not be missed by 1e-15 s and held one step longer.
constexpr double kRestTimeTolerance_s = 1e-9;

bool finite(const ObservedState& s) {
    const ShellState& b = s.shell;
    return std::isfinite(s.time_s) && std::isfinite(b.pose.centre_m.x) && std::isfinite(b.pose.centre_m.y) &&
           std::isfinite(b.pose.angle_rad) && std::isfinite(b.velocity_m_s.x) && std::isfinite(b.velocity_m_s.y) &&
           std::isfinite(b.angular_velocity_rad_s);
}

}  // namespace

ShellTracker::ShellTracker(const Scene& scene, const ShellPose& release, TrackRules rules, GrainWatch grains)
    : scene_(scene),
      rules_(std::move(rules)),
      grains_(std::move(grains)),
      outer_local_m_(shell_outer_polygon_m(scene.shell)),
      release_(release) {
    const ShellProperties props = shell_properties(scene.shell);
    pivot_radius_m_ = props.pivot_radius_m;
    end_centre_x_m_ = end_centre_x_m(scene, props);
    step_s_ = 1.0 / scene.fidelity.step_hz;
    m_.grains_inside = rules_.grains;
}

void ShellTracker::continue_from(const HandOver& from, const ObservedState& now) {
    m_ = from.measured;
    m_.behaviour = Behaviour::running;
    m_.grains_inside = rules_.grains;
    release_ = from.release;
    landing_.vertex = from.landed_vertex;
    samples_taken_ = static_cast<long>(m_.trajectory.size());
    next_sample_step_ = first_step_at(samples_taken_, scene_.fidelity.step_hz, scene_.run.sample_hz);
    now_ = trajectory_sample(now, release_);
    landing_.previous_kinetic_J = now_.kinetic_J;
}

bool ShellTracker::observe(long step, const ObservedState& s) {
    if (!running()) return false;
    const double t = s.time_s;
    if (!finite(s)) {
        end_diverged("the shell's position or velocity is not a finite number", t);
        return false;
    }
    if (!std::isfinite(s.kinetic_J) || !std::isfinite(s.potential_J)) {
        end_diverged("the energy of the shell and its grains is not a finite number", t);
        return false;
    }
    now_ = trajectory_sample(s, release_);
    const double gain = -now_.dissipated_J;
    m_.max_energy_gain_J = std::max(m_.max_energy_gain_J, gain);
    if (gain > kDivergedEnergyShare * rules_.energy_scale_J) {
        end_diverged(fmt::format("the total energy rose {:.3g} J above its value at release (physical runs only "
                                 "lose energy); {}",
                                 gain, rules_.remedy),
                     t);
        return false;
    }

    if (step > 0) check_impact(s);
    landing_.previous_kinetic_J = now_.kinetic_J;
    record_delayed_kinetic(m_, t, step_s_, now_.kinetic_J);
    // The caller's early exit: at this face impact the run has told it all it needs.
    const int end_at = scene_.run.end_at_impact;
    if (end_at > 0 && m_.impacts.size() >= static_cast<std::size_t>(end_at)) {
        m_.ended_early = fmt::format("ended early at face impact {} (run.end_at_impact = {}), at t = {:.4f} s", end_at,
                                     end_at, t);
        finish(Behaviour::time_limit, t);
        return false;
    }

    if (step >= next_sample_step_) {
        m_.trajectory.push_back(now_);
        ++samples_taken_;
        next_sample_step_ = first_step_at(samples_taken_, scene_.fidelity.step_hz, scene_.run.sample_hz);
        if (!check_grains(t, step)) return false;
    }

    // Rest: the lid centre and the rim both slower than the rest speed, for the rest time.
    const double speed_m_s = std::hypot(s.shell.velocity_m_s.x, s.shell.velocity_m_s.y);
    const double rim_speed_m_s = std::fabs(s.shell.angular_velocity_rad_s) * pivot_radius_m_;
    if (speed_m_s < scene_.run.rest_speed_m_s && rim_speed_m_s < scene_.run.rest_speed_m_s) {
        if (rest_since_s_ < 0.0) rest_since_s_ = t;
        if (t - rest_since_s_ >= scene_.run.rest_time_s - kRestTimeTolerance_s) {
            m_.stop_time_s = rest_since_s_;
            finish(m_.impacts.size() <= 1 ? Behaviour::stopped_at_first_impact : Behaviour::stopped, t);
            return false;
        }
    } else {
        rest_since_s_ = -1.0;
    }
    if (s.shell.pose.centre_m.x >= end_centre_x_m_) {
        finish(Behaviour::rolled_to_end, t);
        return false;
    }
    if (t >= scene_.run.time_limit_s - 0.5 * step_s_) {
        finish(Behaviour::time_limit, t);
        return false;
    }
    return true;
}

void ShellTracker::diverge(const ObservedState& s, const std::string& why) {
    if (!running()) return;
    if (finite(s)) now_ = trajectory_sample(s, release_);
    end_diverged(why, s.time_s);
}

void ShellTracker::end_at_last_state() {
    if (running()) finish(Behaviour::time_limit, now_.time_s);
}

void ShellTracker::check_impact(const ObservedState& s) {
    const int n = scene_.shell.sides;
    const double a = s.shell.pose.angle_rad;
    // The lowest vertex, unwrapped: vertex j points straight down when a = pi/n - 2 pi j/n, so
    // j = 1/2 - a n / (2 pi). Vertex 1 is the pivot at release.
    const long lowest = static_cast<long>(std::floor(1.0 - a * n / (2.0 * geom::kPi)));
    if (lowest <= landing_.vertex) {
        landing_.pending = false;
        return;
    }
    const int j = static_cast<int>(((lowest % n) + n) % n);
    const geom::Vec2 arm_m = geom::rotate(outer_local_m_[static_cast<size_t>(j)], a);
    const double height_m = s.shell.pose.centre_m.y + arm_m.y;
    if (height_m >= rules_.contact_tolerance_m) {
        landing_.pending = false;
        return;
    }
    // The vertex's velocity along the ramp's normal: the centre's plus omega x arm.
    const double normal_speed_m_s = s.shell.velocity_m_s.y + s.shell.angular_velocity_rad_s * arm_m.x;
    const double threshold_m_s =
        std::max(kApproachShare * std::fabs(now_.speed_m_s), 0.1 * scene_.run.rest_speed_m_s);
    if (normal_speed_m_s < -threshold_m_s) {
        // Touching but not yet stopped: the impact ends in a later step. The energy "before" is the
        // highest kinetic energy from the last step before the vertex touched through the steps it
        // approaches within the tolerance: gravity raises it until the contact starts taking it, so
        // the peak is the energy just before the impact in either engine. Box2D's tolerance is wider
        // than its contact skin, and its vertex falls freely for a step inside it: the reading before
        // the touch misses that step's gravity work (1-2% of the energy at 1000 Hz). A soft contact
        // (the 3D reference's springs) takes energy from the first step it touches: the last reading
        // before the vertex stops would already be short of what the springs hold.
        const double before_J = landing_.pending ? landing_.kinetic_before_J : landing_.previous_kinetic_J;
        landing_.kinetic_before_J = std::max(before_J, now_.kinetic_J);
        landing_.pending = true;
        return;
    }
    FaceImpact f;
    f.index = static_cast<int>(m_.impacts.size()) + 1;
    f.time_s = s.time_s;
    f.position_m = now_.position_m;
    f.kinetic_before_J = landing_.pending ? landing_.kinetic_before_J : landing_.previous_kinetic_J;
    f.kinetic_after_J = now_.kinetic_J;
    m_.impacts.push_back(f);
    landing_.vertex = lowest;
    landing_.pending = false;
}

bool ShellTracker::check_grains(double time_s, long step) {
    if (rules_.grains <= 0 || !grains_) return true;
    const GrainCheck c = grains_();
    if (!c.trouble.empty()) {
        end_diverged(c.trouble, time_s, c.inside);
        return false;
    }
    m_.grains_inside = c.inside;
    if (c.inside < rules_.grains) {
        end_diverged(fmt::format("{} of {} grains left {}{}; {}", rules_.grains - c.inside, rules_.grains,
                                 rules_.grains_leave_through, step == 0 ? " while they settled before release" : "",
                                 rules_.remedy),
                     time_s, c.inside);
        return false;
    }
    return true;
}

void ShellTracker::finish(Behaviour b, double time_s) {
    m_.behaviour = b;
    m_.end_time_s = time_s;
    m_.distance_m = now_.position_m;
    if (grains_) m_.grains_inside = grains_().inside;
    // The last state is always in the trajectory, so the file ends where the run ended.
    if (m_.trajectory.empty() || m_.trajectory.back().time_s < time_s) m_.trajectory.push_back(now_);
    if (b == Behaviour::rolled_to_end) set_terminal_velocity_at_end(m_, scene_.shell.sides, now_);
}

void ShellTracker::end_diverged(const std::string& why, double time_s, std::optional<int> grains_inside) {
    m_.behaviour = Behaviour::diverged;
    m_.divergence = fmt::format("at t = {:.4f} s: {}", time_s, why);
    m_.end_time_s = time_s;
    m_.distance_m = m_.trajectory.empty() ? 0.0 : m_.trajectory.back().position_m;
    // The count at the end where the model has one: a diverged run says how many grains it kept.
    if (grains_inside)
        m_.grains_inside = *grains_inside;
    else if (grains_)
        m_.grains_inside = grains_().inside;
}

}  // namespace polyroll
