// Measurements from recorded states: see state_tracker.h. The rules and their reasons are the
// tracker's (sim/tracker.cpp); where they differ, the comment says why.
#include "sim/dem3d/state_tracker.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "sim/fill_plan.h"
#include "sim/geometry.h"
#include "sim/sample_clock.h"
#include "sim/shell_pose.h"
#include "sim/shell_properties.h"

namespace polyroll::dem3d {

std::vector<StateRow> parse_states_csv(const std::string& text) {
    constexpr int kColumns = 12;
    std::istringstream in(text);
    std::string line;
    const std::string header = "time_s,x_m,y_m,angle_rad,vx_m_s,vy_m_s,omega_rad_s,kinetic_J,potential_J,fill_ahead_m,fill_up_m,grains_inside";
    if (!std::getline(in, line) || line != header)
        throw std::runtime_error(fmt::format("states.csv: the first line is not the header '{}'", header));
    std::vector<StateRow> rows;
    int line_no = 1;
    while (std::getline(in, line)) {
        ++line_no;
        if (line.empty()) continue;
        double v[kColumns] = {};
        std::istringstream fields(line);
        std::string cell;
        int k = 0;
        try {
            for (; k < kColumns && std::getline(fields, cell, ','); ++k) {
                size_t used = 0;
                v[k] = std::stod(cell, &used);
                if (used != cell.size()) throw std::invalid_argument(cell);
            }
        } catch (const std::exception&) {
            throw std::runtime_error(fmt::format("states.csv line {}: '{}' is not a number", line_no, cell));
        }
        if (k != kColumns || std::getline(fields, cell, ','))
            throw std::runtime_error(
                fmt::format("states.csv line {}: {} columns where {} are expected", line_no, k, kColumns));
        StateRow r;
        r.time_s = v[0];
        r.shell.pose.centre_m = {v[1], v[2]};
        r.shell.pose.angle_rad = v[3];
        r.shell.velocity_m_s = {v[4], v[5]};
        r.shell.angular_velocity_rad_s = v[6];
        r.kinetic_J = v[7];
        r.potential_J = v[8];
        r.fill_offset_m = {v[9], v[10]};
        r.grains_inside = static_cast<int>(v[11]);
        rows.push_back(r);
    }
    return rows;
}

TrajectorySample trajectory_sample(const StateRow& r, const StateRow& release, bool has_fill) {
    TrajectorySample s;
    s.time_s = r.time_s;
    s.position_m = r.shell.pose.centre_m.x - release.shell.pose.centre_m.x;
    s.speed_m_s = r.shell.velocity_m_s.x;
    s.angle_deg = -(r.shell.pose.angle_rad - release.shell.pose.angle_rad) * 180.0 / geom::kPi;
    s.kinetic_J = r.kinetic_J;
    s.potential_J = r.potential_J;
    s.dissipated_J = -(s.kinetic_J + s.potential_J);
    if (has_fill) {
        s.fill_ahead_m = r.fill_offset_m.x;
        s.fill_up_m = r.fill_offset_m.y;
    }
    return s;
}

namespace {

// As the tracker's: a touching vertex still approaching faster than this share of the centre's speed
// has not been stopped by the impact yet; energy may rise above its release value by at most this
// share of the energy scale.
constexpr double kApproachShare = 0.02;
constexpr double kDivergedEnergyShare = 0.5;

bool finite(const StateRow& r) {
    const ShellState& s = r.shell;
    return std::isfinite(r.time_s) && std::isfinite(s.pose.centre_m.x) && std::isfinite(s.pose.centre_m.y) &&
           std::isfinite(s.pose.angle_rad) && std::isfinite(s.velocity_m_s.x) && std::isfinite(s.velocity_m_s.y) &&
           std::isfinite(s.angular_velocity_rad_s) && std::isfinite(r.kinetic_J) && std::isfinite(r.potential_J);
}

class Measurer {
public:
    Measurer(const Scene& scene, const StateRow& release, const TrackRules& rules)
        : scene_(scene), rules_(rules), outer_(shell_outer_polygon_m(scene.shell)), release_(release) {
        pivot_radius_m_ = shell_properties(scene.shell).pivot_radius_m;
        end_centre_x_m_ = end_centre_x_m(scene, shell_properties(scene.shell));
        step_s_ = 1.0 / scene.fidelity.step_hz;
        m_.grains_inside = rules.grains;
    }

    // One row; false once the run has ended.
    bool observe(long step, const StateRow& r) {
        const double t = r.time_s;
        if (!finite(r)) {
            diverge("the shell's position, velocity or energy is not a finite number", t);
            return false;
        }
        now_ = sample(r);
        const double gain = -now_.dissipated_J;
        m_.max_energy_gain_J = std::max(m_.max_energy_gain_J, gain);
        if (gain > kDivergedEnergyShare * rules_.energy_scale_J) {
            diverge(fmt::format("the total energy rose {:.3g} J above its value at release (physical runs only "
                                "lose energy); use a shorter dem3d.contact_time_s",
                                gain),
                    t);
            return false;
        }
        if (step > 0) check_impact(r);
        previous_kinetic_J_ = now_.kinetic_J;
        record_delayed_kinetic(m_, t, step_s_, now_.kinetic_J);

        if (step >= next_sample_step_) {
            m_.trajectory.push_back(now_);
            ++samples_taken_;
            next_sample_step_ = first_step_at(samples_taken_, scene_.fidelity.step_hz, scene_.run.sample_hz);
            m_.grains_inside = r.grains_inside;
            if (r.grains_inside < rules_.grains) {
                diverge(fmt::format("{} of {} grains left the box through its walls or lids; use a shorter "
                                    "dem3d.contact_time_s",
                                    rules_.grains - r.grains_inside, rules_.grains),
                        t);
                return false;
            }
        }

        const double speed_m_s = std::hypot(r.shell.velocity_m_s.x, r.shell.velocity_m_s.y);
        const double rim_speed = std::fabs(r.shell.angular_velocity_rad_s) * pivot_radius_m_;
        if (speed_m_s < scene_.run.rest_speed_m_s && rim_speed < scene_.run.rest_speed_m_s) {
            if (rest_since_s_ < 0.0) rest_since_s_ = t;
            if (t - rest_since_s_ >= scene_.run.rest_time_s - 1e-9) {
                m_.stop_time_s = rest_since_s_;
                finish(m_.impacts.size() <= 1 ? Behaviour::stopped_at_first_impact : Behaviour::stopped, r);
                return false;
            }
        } else {
            rest_since_s_ = -1.0;
        }
        if (r.shell.pose.centre_m.x >= end_centre_x_m_) {
            finish(Behaviour::rolled_to_end, r);
            return false;
        }
        if (t >= scene_.run.time_limit_s - 0.5 * step_s_) {
            finish(Behaviour::time_limit, r);
            return false;
        }
        return true;
    }

    // The rows ended before any rule ended the run (the script stops on the same rules, so only a
    // run cut short): the time limit at the last row.
    void cut_short(const StateRow& last) { finish(Behaviour::time_limit, last); }

    Measurements take() { return std::move(m_); }

private:
    TrajectorySample sample(const StateRow& r) const { return trajectory_sample(r, release_, rules_.grains > 0); }

    void check_impact(const StateRow& r) {
        const int n = scene_.shell.sides;
        const double a = r.shell.pose.angle_rad;
        // The lowest vertex, unwrapped, as in the tracker: vertex 1 is the pivot at release.
        const long lowest = static_cast<long>(std::floor(1.0 - a * n / (2.0 * geom::kPi)));
        if (lowest <= landed_vertex_) {
            impact_pending_ = false;
            return;
        }
        const int j = static_cast<int>(((lowest % n) + n) % n);
        const geom::Vec2 arm = geom::rotate(outer_[static_cast<size_t>(j)], a);
        const double height_m = r.shell.pose.centre_m.y + arm.y;
        if (height_m >= rules_.contact_tolerance_m) {
            impact_pending_ = false;
            return;
        }
        // The vertex's velocity: the centre's plus omega x arm.
        const double normal_speed = r.shell.velocity_m_s.y + r.shell.angular_velocity_rad_s * arm.x;
        const double threshold = std::max(kApproachShare * std::fabs(now_.speed_m_s), 0.1 * scene_.run.rest_speed_m_s);
        if (normal_speed < -threshold) {
            if (!impact_pending_) kinetic_before_J_ = previous_kinetic_J_;
            impact_pending_ = true;
            return;
        }
        FaceImpact f;
        f.index = static_cast<int>(m_.impacts.size()) + 1;
        f.time_s = r.time_s;
        f.position_m = now_.position_m;
        f.kinetic_before_J = impact_pending_ ? kinetic_before_J_ : previous_kinetic_J_;
        f.kinetic_after_J = now_.kinetic_J;
        m_.impacts.push_back(f);
        landed_vertex_ = lowest;
        impact_pending_ = false;
    }

    void finish(Behaviour b, const StateRow& r) {
        m_.behaviour = b;
        m_.end_time_s = r.time_s;
        m_.distance_m = now_.position_m;
        m_.grains_inside = r.grains_inside;
        if (m_.trajectory.empty() || m_.trajectory.back().time_s < r.time_s) m_.trajectory.push_back(now_);
        if (b == Behaviour::rolled_to_end) set_terminal_velocity_at_end(m_, scene_.shell.sides, now_);
    }

    void diverge(const std::string& why, double time_s) {
        m_.behaviour = Behaviour::diverged;
        m_.divergence = fmt::format("at t = {:.4f} s: {}", time_s, why);
        m_.end_time_s = time_s;
        m_.distance_m = m_.trajectory.empty() ? 0.0 : m_.trajectory.back().position_m;
    }

    const Scene& scene_;
    TrackRules rules_;
    std::vector<geom::Vec2> outer_;
    StateRow release_;
    double pivot_radius_m_ = 0.0;
    double end_centre_x_m_ = 0.0;
    double step_s_ = 0.0;
    Measurements m_;
    TrajectorySample now_;
    long next_sample_step_ = 0;
    long samples_taken_ = 0;
    long landed_vertex_ = 1;
    bool impact_pending_ = false;
    double kinetic_before_J_ = 0.0;
    double previous_kinetic_J_ = 0.0;
    double rest_since_s_ = -1.0;
};

}  // namespace

Measurements measure_states(const Scene& scene, const std::vector<StateRow>& rows, const TrackRules& rules) {
    if (rows.empty()) {
        Measurements m;
        m.behaviour = Behaviour::diverged;
        m.divergence = "at t = 0.0000 s: the 3D reference wrote no state";
        return m;
    }
    Measurer measurer(scene, rows.front(), rules);
    for (size_t i = 0; i < rows.size(); ++i)
        if (!measurer.observe(static_cast<long>(i), rows[i])) return measurer.take();
    measurer.cut_short(rows.back());
    return measurer.take();
}

}  // namespace polyroll::dem3d
