// The event-driven rolling polygon of the reduced models: see rolling_polygon.h.
//
// Conventions, shared with world_builder.h and tracker.cpp: the ramp frame has x down the slope and
// y along its normal; phi is the body's clockwise rotation from "face (0, 1) flat on the ramp"; vertex
// k (unwrapped, 1 at release) touches the ramp at x = k * side and is the pivot while
// phi lies in [face(k-1), face(k)], face(j) = 2 pi j / n being the rotation with face (j, j+1) flat.
//
// On a curved track (ramp_profile.h) each pivot turns gravity to the local slope at its own x and
// keeps it until the next impact. The pendulum then stays the autonomous psi'' = a sin(psi) of
// pivot_motion.h, exact along its Taylor series, with one slope per face; and as the centre travels
// from about half a side before the pivot to half a side past it, the pivot's slope is the mean slope
// over that travel to second order, so the potential each face releases matches the track's (the
// books use the track's own height, ramp_profile.h). The slope under the centre, which the grain
// engine uses, differs from it by at most curvature x R: hundredths of a degree for these shells.
#include "sim/reduced/rolling_polygon.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <limits>

#include <fmt/core.h>

#include "sim/errors.h"
#include "sim/reduced/pivot_motion.h"
#include "sim/reduced/root_finder.h"

namespace polyroll::models {

using geom::Vec2;

namespace {

using geom::kPi;
constexpr double kInf = std::numeric_limits<double>::infinity();
// Points per integrator step at which events and the normal force are checked; the series is exact
// between them, and a turning point between two points is found and checked too.
constexpr int kCheckPoints = 2;
// The step a series is built for, as a share of the next face's time estimated from the mean of the
// fastest and slowest rates on the way (expected_event_s): above 1, as that mean overestimates the
// rate where the body climbs slowly.
constexpr double kExpectedEventMargin = 1.25;
// Never shorter: a face rounding a hair ahead would otherwise ask for steps that do not move the body.
constexpr double kShortestWantedStepS = 1e-6;
// Longest integrator step: keeps the event checks dense on a slow, nearly linear stretch.
constexpr double kMaxStepS = 0.1;
// A run needing more steps than this is stuck (for example in ever-faster rocking): ends as diverged.
constexpr long kMaxRollerSteps = 2'000'000;

class Roller {
public:
    Roller(const RollingBody& body, FillMotion fill, const RampFrame& track);
    RollingRun run();

private:
    // The current pivot's constants: the pendulum psi'' = a sin(psi), psi = phi - phi_top.
    struct Pivot {
        long k = 0;
        double d = 0.0;        // pivot to centre of mass
        double inertia = 0.0;  // about the pivot
        double a = 0.0;        // M g d / inertia
        double phi_top = 0.0;  // rotation with the centre of mass straight above the pivot
        double psi_lo = 0.0;   // face(k-1): landing back on the previous face
        double psi_hi = 0.0;   // face(k): landing on the next face
        double psi_end = kInf; // the centre reaching the ramp's end, if within this pivot's range
        // The track's slope at the pivot: its sine and cosine, and the true vertical in the ramp frame.
        double sin_t = 0.0, cos_t = 1.0;
        Vec2 up;
    };
    enum class Event { none, forward, backward, end };

    Vec2 vertex(long k) const { return outer_[static_cast<size_t>(((k % n_) + n_) % n_)]; }
    double face_angle(long j) const { return 2.0 * kPi * static_cast<double>(j) / n_; }
    Pivot make_pivot(long k) const;
    double psi() const { return phi_ - piv_.phi_top; }

    // The body at rotation phi and rate omega about the current pivot (by default, the state now).
    Vec2 centre_from_pivot(double phi) const { return geom::rotate(-1.0 * vertex(piv_.k), -phi); }
    double centre_x() const { return piv_.k * side_ + centre_from_pivot(phi_).x; }
    double kinetic() const { return 0.5 * piv_.inertia * omega_ * omega_; }
    double potential_abs(double phi) const;
    double potential_abs(double cos_phi, double sin_phi) const;
    // v turned by -phi, given its cosine and sine: geom::rotate(v, -phi) to the last bit.
    static Vec2 turned_back(Vec2 v, double cos_phi, double sin_phi) {
        return {cos_phi * v.x + sin_phi * v.y, cos_phi * v.y - sin_phi * v.x};
    }
    TrajectorySample sample(double t, double phi, double omega) const;
    TrajectorySample sample(double t) const { return sample(t, phi_, omega_); }
    // The normal force the pivot must supply at rotation psi (its sine and cosine) turning at the
    // squared rate psi'^2 = w2, taken from the step's energy constant c = psi'^2 / 2 + a cos(psi)
    // (energy_w2): the fill is frozen between impacts and nothing dissipates there.
    double normal_force(double sin_psi, double cos_psi, double w2) const;
    double energy_w2(double cos_psi, double c) const { return std::max(0.0, 2.0 * (c - piv_.a * cos_psi)); }

    // The fill levelled as gravity lay with the shell turned by `levelled_at_rad` (the pour).
    void rebuild_body(double levelled_at_rad);
    void rebuild_body_landed(long face, long new_pivot);
    void impact(int direction);
    void land(long face);
    double barrier(long pivot, long face, bool forward) const;
    void rest();
    void finish(Behaviour b, double end_time);
    void emit_samples_before(double t_end);  // at the current state, for sample times < t_end
    void emit_series_samples(const PendulumSeries& s, double t_end);
    // The points of a series step find_event looked at, in time order up to the event: where the
    // normal force is checked.
    struct Checkpoint {
        double tau = 0.0, psi = 0.0;
    };
    struct StepEvent {
        Event event = Event::none;
        double tau = 0.0;
        std::array<Checkpoint, 2 * kCheckPoints + 2> path{};
        int path_size = 0;
        void add(double tau_s, double psi) { path[static_cast<size_t>(path_size++)] = {tau_s, psi}; }
    };
    void check_normal(const PendulumSeries& s, const StepEvent& step);
    StepEvent find_event(const PendulumSeries& s, double h) const;
    // About when the current pivot's next face comes, from the energy: the step a series is built for
    // (a little longer, so one step mostly reaches it). Infinite where the body would turn back first.
    double expected_event_s() const;
    void handle(Event e);
    void note_negative_normal();  // on the current pivot (hop_pivots)
    void note_friction(double sin_psi, double cos_psi, double rate_rad_s);  // max_friction_share
    // Whether rolling without slipping needs more friction than the track's slip_friction() gives.
    bool slips(double sin_psi, double cos_psi, double rate_rad_s) const;
    // Positive where the pivot holds (a positive normal force, friction enough not to slip), turning
    // non-positive where it stops holding: the value whose root is the model's end of validity.
    double holding_margin(double sin_psi, double cos_psi, double w2, double rate_rad_s) const;
    double friction_force(double sin_psi, double cos_psi, double rate_rad_s) const;

    const RollingBody& b_;
    const FillMotion fill_motion_;
    const RampFrame& tr_;
    std::vector<Vec2> outer_;
    int n_ = 0;
    double side_ = 0.0, radius_ = 0.0;
    double g_ = 0.0;
    // The true vertical at a pivot x_m down the track (its slope there).
    Vec2 up_at(double x_m) const;
    // The vertical the motion about pivot k sees on a curved track: see make_pivot.
    Vec2 face_work_up(long k, Vec2 up_pivot) const;
    // The centre of mass in the ramp frame, turned by phi (its cosine and sine) about vertex k.
    Vec2 centre_of_mass_about(long k, double cos_phi, double sin_phi) const {
        return Vec2{static_cast<double>(k) * side_, 0.0} +
               turned_back(body_.centre_of_mass_m - vertex(k), cos_phi, sin_phi);
    }
    bool has_fill_ = false;

    MassProperties body_;
    // What the run needs of the fill's segments (FillSegments): its mass and which way was up when it
    // levelled. Kept without the segments' polygons, so re-using a face's fill copies no vectors.
    struct LevelledFill {
        Vec2 up;
        MassProperties mass;
    };
    LevelledFill fill_;
    // The fill re-levelled on each face: landing on face k always leaves the polygon in the same
    // orientation (k modulo n), so each is cut once (measured: 6% of a default-scene run).
    std::vector<std::optional<LevelledFill>> landed_fill_;
    Pivot piv_;
    double phi_ = 0.0, omega_ = 0.0, t_ = 0.0;  // omega = dphi/dt, positive rolling down
    double phi0_ = 0.0, start_x_ = 0.0, u0_ = 0.0;
    double dissipated_ = 0.0;
    long highest_landed_ = 1;
    long next_sample_ = 0;
    bool running_ = true;
    long last_hop_pivot_ = std::numeric_limits<long>::min();
    bool start_checked_ = false;  // the next step's start was the last step's last checkpoint
    RollingRun out_;
};

Roller::Roller(const RollingBody& body, FillMotion fill, const RampFrame& track)
    : b_(body), fill_motion_(fill), tr_(track), outer_(body.outer_m) {
    n_ = static_cast<int>(outer_.size());
    side_ = geom::length(outer_[1] - outer_[0]);
    radius_ = geom::length(outer_[0]);
    g_ = tr_.gravity_m_s2;
    has_fill_ = b_.fill_ratio > 0.0 && b_.fill_areal_density_kg_m2 > 0.0;
    phi0_ = phi_ = tr_.start_rotation_rad;
    if (phi0_ < 0.0 || phi0_ > face_angle(1) * (1.0 + 1e-12))
        throw InputError(fmt::format("the release rotation of {:.3f} deg about the downhill vertex is more than one "
                                     "face ({:.3f} deg): the next vertex would start below the ramp",
                                     phi0_ * 180.0 / kPi, 360.0 / n_));
    rebuild_body(tr_.pour_rotation_rad.value_or(phi0_));  // poured where it is released, on vertex 1
    out_.fill_mass_kg = has_fill_ ? fill_.mass.mass_kg : 0.0;
    piv_ = make_pivot(1);
    if (tr_.pour_rotation_rad) {
        // Stood on the vertex with the pile as poured: the whole body balanced past the pivot, its
        // neighbouring faces kept off the ramp as the grain model keeps them.
        phi0_ = phi_ = std::clamp(std::max(0.0, piv_.phi_top) + tr_.release_tilt_rad, 0.0, 0.9 * face_angle(1));
    }
    start_x_ = centre_x();
    u0_ = potential_abs(phi_);
    out_.min_normal_force_N = kInf;
}

Vec2 Roller::up_at(double x_m) const {
    const double theta = tr_.slope_rad_at(x_m);
    return {-std::sin(theta), std::cos(theta)};
}

// The run books the track's own height as its potential (potential_abs), and on a curved track
// that height changes across the shell's height too (ramp_profile.h): gravity held at the pivot's
// slope over a face does a little more work than the booked height falls (a share of about
// kappa y, y the centre of mass's height), and the excess adds up face after face (without the turn,
// 1.8e-6 J a face for the empty small hexagon at 10 deg on a track sagging 1.7 deg/m). So the
// vertical is turned, within that order of the pivot's slope, until the work from the landing on
// face k-1 to the landing on face k equals the fall of the booked height between them: the energy
// closes at every impact, and a rock back onto face k-1 returns it exactly.
Vec2 Roller::face_work_up(long k, Vec2 up_pivot) const {
    auto centre_of_mass_at = [&](double phi) { return centre_of_mass_about(k, std::cos(phi), std::sin(phi)); };
    const Vec2 a = centre_of_mass_at(face_angle(k - 1)), b = centre_of_mass_at(face_angle(k));
    const Vec2 d = b - a;
    const double fall = tr_.height_at_m(b.x, b.y) - tr_.height_at_m(a.x, a.y);
    const double reach = geom::length(d);
    if (!(reach > 0.0) || !(std::fabs(fall) < reach)) return up_pivot;
    // dot(d, up(theta)) with up(theta) = (-sin theta, cos theta) is reach cos(theta + beta).
    const double beta = std::atan2(d.x, d.y);
    const double theta_pivot = std::atan2(-up_pivot.x, up_pivot.y);
    const double c = std::acos(fall / reach);
    auto near_pivot = [&](double t) { return t + 2.0 * kPi * std::round((theta_pivot - t) / (2.0 * kPi)); };
    const double t1 = near_pivot(c - beta), t2 = near_pivot(-c - beta);
    const double theta = std::fabs(t1 - theta_pivot) <= std::fabs(t2 - theta_pivot) ? t1 : t2;
    // The correction is about kappa y tan(theta): 0.06 rad at most on the steepest, tightest tracks
    // allowed. A root further than 0.1 rad from the pivot's slope is not it: keep the pivot's slope.
    if (std::fabs(theta - theta_pivot) > 0.1) return up_pivot;
    return {-std::sin(theta), std::cos(theta)};
}

Roller::Pivot Roller::make_pivot(long k) const {
    Pivot p;
    p.k = k;
    p.up = up_at(k * side_);
    if (tr_.curved()) p.up = face_work_up(k, p.up);
    p.sin_t = -p.up.x;
    p.cos_t = p.up.y;
    const Vec2 v = vertex(k);
    const Vec2 r0 = body_.centre_of_mass_m - v;
    p.d = geom::length(r0);
    p.inertia = inertia_about(body_, v);
    p.a = p.inertia > 0.0 ? body_.mass_kg * g_ * p.d / p.inertia : 0.0;
    // Turned by phi, the arm r0 points at atan2(r0) - phi in the ramp frame; it is straight up
    // (along the true vertical, theta + pi/2) at phi_top. Taken within half a turn of this pivot's range.
    const double mid = face_angle(k - 1) + kPi / n_;
    const double theta = std::atan2(p.sin_t, p.cos_t);
    p.phi_top = std::atan2(r0.y, r0.x) - theta - kPi / 2.0;
    p.phi_top += 2.0 * kPi * std::round((mid - p.phi_top) / (2.0 * kPi));
    p.psi_lo = face_angle(k - 1) - p.phi_top;
    p.psi_hi = face_angle(k) - p.phi_top;
    // The centre is at x = k side + R sin(phi - mid) while k is the pivot.
    const double reach = (tr_.end_centre_x_m - k * side_) / radius_;
    if (reach < std::sin(kPi / n_)) p.psi_end = mid + std::asin(std::max(-1.0, reach)) - p.phi_top;
    return p;
}

double Roller::potential_abs(double phi) const { return potential_abs(std::cos(phi), std::sin(phi)); }

double Roller::potential_abs(double cos_phi, double sin_phi) const {
    const Vec2 cm = centre_of_mass_about(piv_.k, cos_phi, sin_phi);
    // A curved track's own height, as the grain tracker books it: the per-pivot slope is the model's
    // approximation of the motion, not of the energy.
    if (tr_.curved()) return body_.mass_kg * g_ * tr_.height_at_m(cm.x, cm.y);
    return body_.mass_kg * g_ * geom::dot(cm, piv_.up);
}

TrajectorySample Roller::sample(double t, double phi, double omega) const {
    TrajectorySample s;
    s.time_s = t;
    // The centre and the centre of mass turned alike: one sine and cosine for both.
    const double cos_phi = std::cos(phi), sin_phi = std::sin(phi);
    const Vec2 c = turned_back(-1.0 * vertex(piv_.k), cos_phi, sin_phi);
    s.position_m = piv_.k * side_ + c.x - start_x_;
    s.speed_m_s = omega * c.y;  // the centre turns about the pivot: v = omega x (centre - pivot)
    // From the scene's release pose (release_pose(), what rolling_pose() draws from): the tipped
    // release's balance turn shows as a first row turned by it.
    s.angle_deg = (phi - tr_.start_rotation_rad) * 180.0 / kPi;
    s.kinetic_J = 0.5 * piv_.inertia * omega * omega;
    s.potential_J = potential_abs(cos_phi, sin_phi) - u0_;
    s.dissipated_J = dissipated_;
    return s;
}

double Roller::normal_force(double sp, double cp, double w2) const {
    // N = M (g cos theta + a_cm . y): the centre of mass turns about the fixed pivot, so
    // a_cm.y = -phi'' r.x - phi'^2 r.y with r the arm from pivot to centre of mass.
    const double sin_t = piv_.sin_t, cos_t = piv_.cos_t;
    const double rx = piv_.d * (sp * cos_t - cp * sin_t);  // d sin(psi - theta)
    const double ry = piv_.d * (cp * cos_t + sp * sin_t);  // d cos(psi - theta)
    return body_.mass_kg * (g_ * cos_t - piv_.a * sp * rx - w2 * ry);
}

double Roller::friction_force(double sp, double cp, double rate) const {
    // M a_cm = M g + (F, N) in the ramp frame, the centre of mass turning about the fixed pivot:
    // a_cm.x = phi'' r.y - phi'^2 r.x (see normal_force for a_cm.y).
    const double sin_t = piv_.sin_t, cos_t = piv_.cos_t;
    const double rx = piv_.d * (sp * cos_t - cp * sin_t), ry = piv_.d * (cp * cos_t + sp * sin_t);
    return body_.mass_kg * (piv_.a * sp * ry - rate * rate * rx - g_ * sin_t);
}

void Roller::note_friction(double sp, double cp, double rate) {
    const double n = normal_force(sp, cp, rate * rate);
    if (!(n > 0.0)) return;
    out_.max_friction_share = std::max(out_.max_friction_share, std::fabs(friction_force(sp, cp, rate)) / n);
}

bool Roller::slips(double sp, double cp, double rate) const {
    if (tr_.slip_friction() <= 0.0) return false;
    const double n = normal_force(sp, cp, rate * rate);
    return n > 0.0 && std::fabs(friction_force(sp, cp, rate)) > tr_.slip_friction() * n;
}

double Roller::holding_margin(double sp, double cp, double w2, double rate) const {
    const double nf = normal_force(sp, cp, w2);
    if (tr_.slip_friction() <= 0.0) return nf;
    const double n = normal_force(sp, cp, rate * rate);
    const double spare = n > 0.0 ? tr_.slip_friction() * n - std::fabs(friction_force(sp, cp, rate)) : nf;
    return std::min(nf, spare);
}

void Roller::rebuild_body_landed(long face, long new_pivot) {
    // Levelled to gravity as the new pivot turns it (the slope the motion after the impact sees).
    const Vec2 up = up_at(new_pivot * side_);
    if (tr_.curved()) {
        // The vertical differs from face to face: no orientation repeats exactly.
        const FillSegments f =
            fill_segments(b_.inner_m, geom::rotate(up, phi_), b_.fill_ratio, b_.fill_areal_density_kg_m2);
        fill_ = {f.up, f.mass};
        body_ = combine(b_.shell, fill_.mass);
        return;
    }
    const size_t key = static_cast<size_t>(((face % n_) + n_) % n_);
    if (landed_fill_.empty()) landed_fill_.resize(static_cast<size_t>(n_));
    if (!landed_fill_[key]) {
        const FillSegments f =
            fill_segments(b_.inner_m, geom::rotate(up, phi_), b_.fill_ratio, b_.fill_areal_density_kg_m2);
        landed_fill_[key] = LevelledFill{f.up, f.mass};
    }
    fill_ = *landed_fill_[key];
    body_ = combine(b_.shell, fill_.mass);
}

void Roller::rebuild_body(double levelled_at_rad) {
    if (!has_fill_) {
        body_ = b_.shell;
        return;
    }
    // The body frame sees gravity turned back by the body's rotation when the fill was levelled.
    // Vertex 1 is the pivot at release.
    const FillSegments f = fill_segments(b_.inner_m, geom::rotate(up_at(side_), levelled_at_rad), b_.fill_ratio,
                                         b_.fill_areal_density_kg_m2);
    fill_ = {f.up, f.mass};
    body_ = combine(b_.shell, fill_.mass);
}

Roller::StepEvent Roller::find_event(const PendulumSeries& s, double h) const {
    const double hi = std::min(piv_.psi_hi, piv_.psi_end), lo = piv_.psi_lo;
    auto crossed = [&](double p) { return p >= hi || p <= lo; };
    double ta = 0.0, pa = 0.0, ra = 0.0;
    s.psi_and_rate(0.0, pa, ra);
    StepEvent out;
    out.add(0.0, pa);
    for (int i = 1; i <= kCheckPoints; ++i) {
        double tb = h * i / kCheckPoints, pb = 0.0, rb = 0.0;
        s.psi_and_rate(tb, pb, rb);
        if (ra * rb < 0.0) {
            // A turning point inside: the extreme value may lie beyond a boundary though both ends do
            // not, and the normal force is checked there too.
            const double turn = ra > 0.0 ? 1.0 : -1.0;
            auto rate = [&](double t) {
                Slope v;
                s.rate_and_acceleration(t, v.value, v.derivative);
                return Slope{turn * v.value, turn * v.derivative};
            };
            const double te = first_root(rate, ta, turn * ra, tb, turn * rb, 0.0);
            const double pe = s.psi(te);
            if (crossed(pe)) {
                tb = te;
                pb = pe;
            } else {
                out.add(te, pe);
                // Crossed after the turn: searched from the turn on. A step that starts on a face
                // (just landed) and rocks back onto it would otherwise find the face at tau = 0,
                // moving away from it: an impact that never happened.
                if (crossed(pb)) {
                    ta = te;
                    pa = pe;
                }
            }
        }
        if (crossed(pb)) {
            const bool upper = pb >= hi;
            const double target = upper ? hi : lo;
            // target - psi going up, psi - target going down: positive until the crossing.
            const double side = upper ? 1.0 : -1.0;
            auto gap = [&](double t) {
                double psi = 0.0, rate = 0.0;
                s.psi_and_rate(t, psi, rate);
                return Slope{side * (target - psi), -side * rate};
            };
            const double tau = first_root(gap, ta, side * (target - pa), tb, side * (target - pb), 0.0);
            out.add(tau, target);
            out.event = !upper ? Event::backward : (piv_.psi_end <= piv_.psi_hi ? Event::end : Event::forward);
            out.tau = tau;
            return out;
        }
        out.add(tb, pb);
        ta = tb;
        pa = pb;
        ra = rb;
    }
    out.tau = h;
    return out;
}

double Roller::expected_event_s() const {
    if (omega_ == 0.0) return kInf;
    const double psi0 = psi(), target = omega_ > 0.0 ? std::min(piv_.psi_hi, piv_.psi_end) : piv_.psi_lo;
    // Slowest where the centre of mass is highest: over the top if the arc passes it, else at the end
    // nearer the top.
    const double cos0 = std::cos(psi0);
    const double cos_highest =
        psi0 * target <= 0.0 ? 1.0 : (std::fabs(target) < std::fabs(psi0) ? std::cos(target) : cos0);
    const double w2_min = omega_ * omega_ + 2.0 * piv_.a * (cos0 - cos_highest);
    if (!(w2_min > 0.0)) return kInf;
    const double expected = std::fabs(target - psi0) / (0.5 * (std::fabs(omega_) + std::sqrt(w2_min)));
    return std::max(kExpectedEventMargin * expected, kShortestWantedStepS);
}

void Roller::check_normal(const PendulumSeries& s, const StepEvent& step) {
    double sin0 = 0.0, cos0 = 0.0;
    s.sin_cos_psi(0.0, sin0, cos0);
    const double c = 0.5 * omega_ * omega_ + piv_.a * cos0;
    // A step that carries on from the previous one on the same pivot starts where that one's last
    // checkpoint was.
    for (int i = start_checked_ ? 1 : 0; i < step.path_size; ++i) {
        const Checkpoint& p = step.path[static_cast<size_t>(i)];
        double sp = 0.0, cp = 0.0;
        s.sin_cos_psi(p.tau, sp, cp);  // the series' own sine and cosine: no trigonometry
        const double w2 = energy_w2(cp, c), rate = std::sqrt(w2);
        const double nf = normal_force(sp, cp, w2);
        out_.min_normal_force_N = std::min(out_.min_normal_force_N, nf);
        note_friction(sp, cp, rate);
        if (nf < 0.0) note_negative_normal();
        const bool slip = slips(sp, cp, rate);
        if ((nf < 0.0 || slip) && out_.model_valid) {
            // When it turned negative (or began to slip), between this checkpoint and the previous one,
            // where it held.
            auto margin = [&](double tau) {
                const double psi = s.psi(tau);
                return holding_margin(std::sin(psi), std::cos(psi), energy_w2(std::cos(psi), c), s.rate(tau));
            };
            const double from = i > 0 ? step.path[static_cast<size_t>(i - 1)].tau : p.tau;
            const double when = i > 0 ? first_root(margin, from, margin(from), p.tau, margin(p.tau), 0.0) : p.tau;
            out_.model_valid = false;
            out_.model_invalid_time_s = t_ + when;
        }
    }
    start_checked_ = step.event == Event::none;
}

void Roller::note_negative_normal() {
    if (piv_.k == last_hop_pivot_) return;
    last_hop_pivot_ = piv_.k;
    ++out_.hop_pivots;
}

void Roller::emit_series_samples(const PendulumSeries& s, double t_end) {
    for (;;) {
        const double ts = tr_.sample_time(next_sample_);
        if (ts >= t_end) break;
        const double tau = std::max(0.0, ts - t_);
        double psi = 0.0, rate = 0.0;
        s.psi_and_rate(tau, psi, rate);
        out_.measured.trajectory.push_back(sample(ts, psi + piv_.phi_top, rate));
        ++next_sample_;
    }
}


void Roller::emit_samples_before(double t_end) {
    for (;;) {
        const double ts = tr_.sample_time(next_sample_);
        if (ts >= t_end) break;
        out_.measured.trajectory.push_back(sample(ts));
        ++next_sample_;
    }
}

void Roller::impact(int direction) {
    // Face `face` lands; the vertex beyond the pivot becomes the new pivot.
    const long face = direction > 0 ? piv_.k : piv_.k - 1;
    const long new_k = direction > 0 ? piv_.k + 1 : piv_.k - 1;
    phi_ = face_angle(face);
    const double kinetic_before = kinetic();
    const Vec2 r_a = body_.centre_of_mass_m - vertex(piv_.k), r_b = body_.centre_of_mass_m - vertex(new_k);
    const double inertia_b = inertia_about(body_, vertex(new_k));
    // Angular momentum about the new pivot: (I0 + M r_A . r_B) omega_A = (I0 + M |r_B|^2) omega_B.
    double w = omega_ * (body_.inertia_cm_kg_m2 + body_.mass_kg * geom::dot(r_a, r_b)) / inertia_b;
    // Turning back about the new pivot would push the old one into the ramp: the face stays down.
    if (w * omega_ <= 0.0) w = 0.0;
    const double kinetic_after = 0.5 * inertia_b * w * w;
    dissipated_ += kinetic_before - kinetic_after;
    {
        // The impulse at the new pivot is the change of momentum: M (v_cm after - v_cm before), each
        // v_cm = omega x (centre of mass - pivot), in the ramp frame (clockwise omega: (r.y, -r.x) omega).
        const Vec2 a_r = geom::rotate(r_a, -phi_), b_r = geom::rotate(r_b, -phi_);
        const Vec2 p{w * b_r.y - omega_ * a_r.y, -(w * b_r.x - omega_ * a_r.x)};
        if (p.y > 0.0)
            out_.max_impact_friction_share = std::max(out_.max_impact_friction_share, std::fabs(p.x) / p.y);
        // An impact that needs more friction than the ramp gives: the real vertex slides as it lands.
        if (tr_.slip_friction() > 0.0 && out_.model_valid && !(p.y > 0.0 && std::fabs(p.x) <= tr_.slip_friction() * p.y)) {
            out_.model_valid = false;
            out_.model_invalid_time_s = t_;
        }
    }

    // A full polygon's fill is the whole inside whatever the orientation: nothing to re-level.
    if (has_fill_ && fill_motion_ == FillMotion::relevel && b_.fill_ratio < 1.0) {
        // The surface re-levels; the drop of the fill's centre of mass turns into no kinetic energy.
        const Vec2 old_cm = fill_.mass.centre_of_mass_m;
        rebuild_body_landed(face, new_k);
        const double drop_J = fill_.mass.mass_kg * g_ * geom::dot(old_cm - fill_.mass.centre_of_mass_m, fill_.up);
        dissipated_ += drop_J;
        out_.relevel_dissipated_J += drop_J;
        const double inertia_new = inertia_about(body_, vertex(new_k));
        w = (w > 0.0 ? 1.0 : w < 0.0 ? -1.0 : 0.0) * std::sqrt(2.0 * kinetic_after / inertia_new);
    }
    piv_ = make_pivot(new_k);
    omega_ = w;
    if (direction > 0 && new_k > highest_landed_) {
        highest_landed_ = new_k;
        FaceImpact f;
        f.index = static_cast<int>(out_.measured.impacts.size()) + 1;
        f.time_s = t_;
        f.position_m = centre_x() - start_x_;
        f.kinetic_before_J = kinetic_before;
        f.kinetic_after_J = kinetic_after;
        out_.measured.impacts.push_back(f);
    }
    land(face);
}

double Roller::barrier(long pivot, long face, bool forward) const {
    // The rise of the centre of mass needed to leave face `face` about `pivot`: over the top if the
    // top lies within the pivot's range, else to the far face.
    const Pivot p = make_pivot(pivot);
    const double psi_now = face_angle(face) - p.phi_top;
    const double lo = forward ? psi_now : p.psi_lo, hi = forward ? p.psi_hi : psi_now;
    const double highest = (lo <= 0.0 && hi >= 0.0) ? 1.0 : std::max(std::cos(lo), std::cos(hi));
    return body_.mass_kg * g_ * p.d * (highest - std::cos(psi_now));
}

void Roller::land(long face) {
    if (omega_ == 0.0) {
        // At rest on the face: it tips about whichever end vertex gravity turns it over, if any.
        const Pivot front = make_pivot(face + 1), back = make_pivot(face);
        if (face_angle(face) - front.phi_top > 0.0) piv_ = front;
        else if (face_angle(face) - back.phi_top < 0.0) piv_ = back;
    }
    // Confined: too little energy to leave the face either way, so it rocks on it and loses energy at
    // every landing. It has stopped (as the tracker sees it) once its speeds are below the rest speed.
    // The speeds first: every landing asks, and they are the cheapest to work out (the barriers make
    // two pivots).
    const double rim_speed = std::fabs(omega_) * radius_;
    if (!(rim_speed < tr_.rest_speed_m_s)) return;
    const double centre_speed = std::fabs(sample(t_).speed_m_s);
    if (!(centre_speed < tr_.rest_speed_m_s)) return;
    const double ke = kinetic();
    const bool confined = ke < barrier(face + 1, face, true) && ke < barrier(face, face, false);
    if (confined) rest();
}

void Roller::rest() {
    const double stop = t_;
    out_.measured.stop_time_s = stop;
    dissipated_ += kinetic();  // what is left of the rocking
    omega_ = 0.0;
    const bool in_time = stop + tr_.rest_time_s <= tr_.time_limit_s;
    const double end = in_time ? stop + tr_.rest_time_s : tr_.time_limit_s;
    emit_samples_before(end);
    t_ = end;
    if (!in_time) finish(Behaviour::time_limit, end);
    else finish(out_.measured.impacts.size() <= 1 ? Behaviour::stopped_at_first_impact : Behaviour::stopped, end);
}

void Roller::finish(Behaviour b, double end_time) {
    running_ = false;
    Measurements& m = out_.measured;
    m.behaviour = b;
    m.end_time_s = end_time;
    const TrajectorySample last = sample(end_time);
    m.distance_m = last.position_m;
    if (m.trajectory.empty() || m.trajectory.back().time_s < end_time) m.trajectory.push_back(last);
    if (b == Behaviour::rolled_to_end) set_terminal_velocity(m, n_);
}

void Roller::handle(Event e) {
    switch (e) {
        case Event::end: finish(Behaviour::rolled_to_end, t_); break;
        case Event::forward: impact(+1); break;
        case Event::backward: impact(-1); break;
        case Event::none: break;
    }
}

RollingRun Roller::run() {
    emit_samples_before(std::nextafter(0.0, 1.0));  // the release state is the first row
    for (long j = 0; j <= 1; ++j)
        if (phi_ == face_angle(j)) land(j);  // released flat on a face: rests or tips
    while (running_) {
        if (++out_.steps > kMaxRollerSteps || !std::isfinite(omega_) || !std::isfinite(phi_)) {
            out_.measured.behaviour = Behaviour::diverged;
            out_.measured.divergence =
                fmt::format("at t = {:.4f} s: the reduced model took more than {} steps", t_, kMaxRollerSteps);
            out_.measured.end_time_s = t_;
            if (!out_.measured.trajectory.empty())
                out_.measured.distance_m = out_.measured.trajectory.back().position_m;
            running_ = false;
            break;
        }
        const double left = tr_.time_limit_s - t_;
        if (left <= 1e-12 * std::max(1.0, tr_.time_limit_s)) {
            finish(Behaviour::time_limit, t_);
            break;
        }
        if (tr_.stop_when_invalid && !out_.model_valid) {
            out_.measured.end_time_s = t_;
            out_.measured.distance_m = sample(t_).position_m;
            running_ = false;
            break;
        }
        const PendulumSeries s(psi(), omega_, piv_.a, std::min({expected_event_s(), kMaxStepS, left}));
        const double h = std::min({s.accurate_step_s(), kMaxStepS, left});
        const StepEvent found = find_event(s, h);
        const Event event = found.event;
        const double tau = found.tau;
        check_normal(s, found);
        emit_series_samples(s, t_ + tau);
        const double rate = s.rate(tau);
        const double psi_new = event == Event::none     ? s.psi(tau)
                               : event == Event::backward ? piv_.psi_lo
                               : event == Event::forward  ? piv_.psi_hi
                                                          : piv_.psi_end;
        t_ = event == Event::none && tau == left ? tr_.time_limit_s : t_ + tau;
        phi_ = psi_new + piv_.phi_top;
        omega_ = rate;
        handle(event);
    }
    out_.measured.max_energy_gain_J = 0.0;
    for (const TrajectorySample& s : out_.measured.trajectory)
        out_.measured.max_energy_gain_J = std::max(out_.measured.max_energy_gain_J,
                                                   s.kinetic_J + s.potential_J + s.dissipated_J);
    if (!std::isfinite(out_.min_normal_force_N)) out_.min_normal_force_N = 0.0;
    return out_;
}

}  // namespace

RollingRun roll(const RollingBody& body, FillMotion fill, const RampFrame& track) {
    if (body.outer_m.size() < 3) throw InputError("a rolling polygon needs at least 3 sides");
    Roller r(body, fill, track);
    return r.run();
}

}  // namespace polyroll::models
