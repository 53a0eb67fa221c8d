// An empty shell after lift-off, event-driven: see free_body.h.
//
// Conventions, those of shell_pose.h and tracker.cpp: the ramp frame has x down the slope and y along
// its normal, the surface at y = 0; the angle a is counter-clockwise (rolling down turns it
// negative); vertex j (unwrapped) points straight down at a = pi/n - 2 pi j/n, so the lowest vertex is
// floor(1 - a n / (2 pi)), and vertex 1 was the pivot at release.
//
// On a curved track (ramp_profile.h) gravity is turned to the local slope under the centre, as the
// grain engine turns it, once at the start of each stretch, and stretches there last at most
// kCurvedStretchS: each stays an exact parabola or Taylor series of a constant gravity, and the
// centre moves a few millimetres within one (thousandths of a degree of slope at these curvatures).
#include "sim/reduced/free_body.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>

#include "sim/reduced/pivot_motion.h"
#include "sim/reduced/root_finder.h"
#include "sim/reduced/slide_motion.h"

namespace polyroll::models {

using geom::Vec2;

namespace {

using geom::kPi;
// A contact stretch follows a Taylor series, exact to rounding (the rigid model's pendulum for a
// sticking vertex, pivot_motion.h; slide_motion.h for a sliding one), so it needs no small steps; its
// events are looked for on a grid of series evaluations this far apart in time and in turn, which
// bounds how briefly an event could come and go unseen.
constexpr double kContactGridS = 10e-3;
constexpr double kContactTurnRad = 0.05;
// Events inside a step are found to this time (first_root, root_finder.h).
constexpr double kEventTolS = 1e-9;
// A vertex closer to the ramp than this at the start is on it.
constexpr double kTouchM = 1e-9;
// Shortest step of the search for a flight's touch-down (see flight_stretch).
constexpr double kFlightMinStepS = 1e-4;
// More stretches than this in a row, each shorter than kChatterS: the run is caught between two
// contact states (two vertices on the ramp, a grazing lift-off: contacts it does not model) and stops.
constexpr int kMaxChatter = 100;
constexpr double kChatterS = 1e-6;
// Far more events than a 2.5 m ramp gives (about 4 per face): a run stuck in a loop stops.
constexpr long kMaxFreeBodySteps = 2'000'000;
// The longest stretch on a curved track, between two turns of gravity.
constexpr double kCurvedStretchS = 1e-3;

// Gravity as one stretch sees it: the slope theta (radians), and g along the ramp (gx, down it) and
// its normal (gy, negative; g_cos = -gy).
struct Gravity {
    double theta = 0.0, cos_theta = 1.0, sin_theta = 0.0;
    double gx = 0.0, gy = 0.0, g_cos = 0.0;
};

struct State {
    double x = 0, y = 0, a = 0, vx = 0, vy = 0, w = 0;  // centre, angle, their rates (w counter-clockwise)
};

enum class Phase { flight, stick, slide };

// How long a vertex's height above the ramp in flight surely stays positive, from its derivatives now
// (h, h1 = dh/dt, h2, h3 the second and third) and a bound k4 on the fourth's size over the flight:
// the Taylor polynomial with that remainder, L(t) = h + h1 t + h2 t^2/2 + h3 t^3/6 - k4 t^4/24, is a
// lower bound of the height, and L > 0 on (0, d] wherever its Bernstein coefficients on [0, d] are all
// non-negative and the last positive. Halves d from d_max until they are; 0 if 30 halvings do not.
// Unlike a second-order bound, this proves a step for the vertex just left, which rises as t^3 (its
// height, speed and acceleration along the ramp's normal all vanish at lift-off).
// A bracketing aid, not a root finder: it only says how far the search may step without passing a
// touch; the touch itself is located by first_root (root_finder.h).
double positive_for(double h, double h1, double h2, double h3, double k4, double d_max) {
    double d = d_max;
    for (int i = 0; i < 30; ++i, d *= 0.5) {
        const double c1 = h1 * d, c2 = h2 * d * d / 2.0, c3 = h3 * d * d * d / 6.0, c4 = -k4 * d * d * d * d / 24.0;
        // Power basis to Bernstein basis of degree 4: b_i = sum over k <= i of C(i,k) / C(4,k) c_k.
        const double b1 = h + c1 / 4.0;
        const double b2 = h + c1 / 2.0 + c2 / 6.0;
        const double b3 = h + 3.0 * c1 / 4.0 + c2 / 2.0 + c3 / 4.0;
        const double b4 = h + c1 + c2 + c3 + c4;
        if (b1 >= 0.0 && b2 >= 0.0 && b3 >= 0.0 && b4 > 0.0) return d;
    }
    return 0.0;
}

class FreeBodySolver {
public:
    FreeBodySolver(const FreeBody& body, const RampFrame& frame, const FreeBodyStart& start);
    FreeBodyMotion run();
    // The row a run recording every tracker step would have at `step` (see FreeBodyMotion::row_at_step).
    std::optional<FreeBodyRow> row_at_step(long step, double step_hz, long first_step) const;

private:
    struct Contact {
        double F = 0, N = 0;  // friction (along x) and normal force on the shell, N; 0 in flight
    };

    // The turn of the body: the cosine and sine of its angle, worked out once per state.
    struct Turn {
        double c = 1.0, s = 0.0;
    };
    static Turn turn_of(double a) { return {std::cos(a), std::sin(a)}; }
    size_t index(long j) const { return static_cast<size_t>(((j % n_) + n_) % n_); }
    // Vertex j (unwrapped) relative to the centre, with the body turned by t (or by angle a).
    Vec2 arm(long j, Turn t) const {
        const Vec2 u = unit_[index(j)];
        return {radius_ * (u.x * t.c - u.y * t.s), radius_ * (u.x * t.s + u.y * t.c)};
    }
    Vec2 arm(long j, double a) const { return arm(j, turn_of(a)); }
    long lowest(double a) const { return static_cast<long>(std::floor(1.0 - a * n_ / (2.0 * kPi))); }
    Vec2 vertex_velocity(const State& s, Vec2 r) const { return {s.vx - s.w * r.y, s.vy + s.w * r.x}; }

    // The forces with the contact vertex at r from the centre.
    Contact contact(const State& s, Phase p, Vec2 r) const;
    Contact contact(const State& s, Phase p) const { return contact(s, p, arm(on_, s.a)); }
    void project(State& s, Phase p) const;
    State flight_at(const State& s, double tau) const { return flight_at(s, tau, g_); }
    static State flight_at(const State& s, double tau, const Gravity& g);
    Gravity gravity_at(double x_m) const;
    // The longest stretch from now: to the time limit, and on a curved track kCurvedStretchS.
    double stretch_cap_s() const;

    // What ends a contact step. Each has a value that is positive before it and turns non-positive
    // where it happens (a neighbour's height, the normal force, the friction to spare, ...).
    enum class Event { none, touch, lift, slip, grip, end, rest };
    static constexpr Event kContactEvents[] = {Event::touch, Event::lift, Event::slip, Event::grip, Event::end, Event::rest};
    // c: the contact forces at s if already worked out (they are the same for every event).
    double event_value(const State& s, Phase p, Event e, Turn t, const Contact* c = nullptr) const;

    // The sticking vertex's pendulum (pivot_motion.h): psi is the turn past the centre straight above
    // the pivot, psi = beta + a - theta + pi/2 for the contact vertex's beta.
    double psi_of(double a) const { return beta_[index(on_)] + a - g_.theta + kPi / 2.0; }
    // The state at tau into a series begun at psi0 from angle a0, and the body's turn there.
    // `on` and `pivot_x` are those of the stretch (on_, pivot_x_ as it began): the stretch is kept
    // for the dense output after they change.
    State stick_state(const PendulumSeries& ps, const Gravity& g, long on, double pivot_x, double psi0, double a0,
                      double tau, Turn& t) const;
    // The same for a sliding vertex (slide_motion.h), whose direction from the centre is phi = beta + a.
    State slide_state(const SlideSeries& ss, long on, double phi0, double a0, double tau, Turn& t) const;
    // The state on the ramp with the contact vertex in direction (c_phi, s_phi) from the centre: the
    // body's turn, its y and vy (the vertex on the ramp); x, vx, a and w as given.
    State on_vertex(long on, double c_phi, double s_phi, double x, double vx, double a, double w, Turn& t) const;

    void stick_stretch();
    void slide_stretch();
    // A contact stretch along a series, as long as it stays accurate (span, s): events looked for on
    // a grid of series evaluations and located by false position. state_at(tau, turn) gives the state.
    template <class StateAt>
    void follow(Phase p, double span, StateAt state_at);
    // What follows a contact stretch's event (s_ and t_ at it).
    void after_contact_event(Event e);
    void flight_stretch();
    // Resolves the impact of vertex j (unwrapped) and picks the stretch that follows.
    void impact(long j);
    // The stretch on vertex j with the vertex's velocity along the ramp as it is (after an impact or a
    // slip's end): sticking if it is at rest and friction holds it, flying if the ramp would pull.
    void settle_on(long j);

    TrajectorySample sample(const State& s, double t) const;
    // M g times the centre's height: on a curved track the track's own (ramp_profile.h), as the grain
    // tracker books it.
    double potential_J(const State& s) const {
        const double height_m = frame_.curved() ? frame_.height_at_m(s.x, s.y) : geom::dot({s.x, s.y}, up_);
        return m_ * frame_.gravity_m_s2 * height_m;
    }
    // Rows for the sample times before t_end of the stretch begun at t_, whose state tau into it is
    // state_at(tau); the stretch is kept as the run's dense output.
    void emit_rows_before(double t_end, std::function<State(double)> state_at);
    void note_landing(long j, double kinetic_before_J);
    void finish(Behaviour b);
    void stop_unsupported(const std::string& why);

    const RampFrame frame_;
    int n_ = 0;
    double radius_ = 0.0, m_ = 0.0, inertia_ = 0.0, mu_ = 0.0;
    double inv_m_ = 0.0, inv_i_ = 0.0;
    Gravity g_;  // of the stretch under way
    double pendulum_a_ = 0.0;  // M g R / I_pivot, 1/s^2
    std::vector<double> beta_;
    std::vector<Vec2> unit_;  // (cos beta, sin beta) of each vertex
    Vec2 up_;  // the vertical of a straight track
    double start_x_ = 0.0, start_a_ = 0.0, potential_offset_J_ = 0.0;

    State s_;
    double t_ = 0.0;
    Phase phase_ = Phase::stick;
    long on_ = 1;          // the vertex in contact (stick, slide)
    int slip_sign_ = 0;    // sign of the vertex's velocity along the ramp while sliding
    double pivot_x_ = 0.0; // where the sticking vertex is
    long landed_ = 1;
    long next_row_ = 0;
    int chatter_ = 0;  // stretches in a row shorter than kChatterS
    bool running_ = true;
    bool finished_ = false;  // ended by finish() (not unsupported)
    FreeBodyMotion out_;
    // The run's stretches in time order, each from t0 to t_end: the dense output.
    struct Stretch {
        double t0 = 0.0, t_end = 0.0;
        long landed = 1;
        std::function<State(double)> at;
    };
    std::vector<Stretch> stretches_;
};

FreeBodySolver::FreeBodySolver(const FreeBody& body, const RampFrame& frame, const FreeBodyStart& start) : frame_(frame) {
    n_ = static_cast<int>(body.outer_m.size());
    radius_ = geom::length(body.outer_m[0]);
    for (const Vec2& v : body.outer_m) {
        beta_.push_back(std::atan2(v.y, v.x));
        unit_.push_back({std::cos(beta_.back()), std::sin(beta_.back())});
    }
    m_ = body.mass_kg;
    inertia_ = body.inertia_kg_m2;
    inv_m_ = 1.0 / m_;
    inv_i_ = 1.0 / inertia_;
    mu_ = frame.friction;
    pendulum_a_ = m_ * frame.gravity_m_s2 * radius_ / (inertia_ + m_ * radius_ * radius_);
    start_x_ = start.release.centre_m.x;
    start_a_ = start.release.angle_rad;
    const ShellState& st = start.state;
    s_ = {st.pose.centre_m.x, st.pose.centre_m.y, st.pose.angle_rad, st.velocity_m_s.x, st.velocity_m_s.y,
          st.angular_velocity_rad_s};
    g_ = gravity_at(s_.x);
    up_ = {-g_.sin_theta, g_.cos_theta};
    t_ = start.time_s;
    landed_ = start.landed_vertex;
    out_.measured = start.measured;
    out_.measured.behaviour = Behaviour::running;
    next_row_ = static_cast<long>(out_.measured.trajectory.size());
    // Booked potential = M g (up . centre) - offset, continuous with the records so far.
    potential_offset_J_ = potential_J(s_) - start.potential_J;
}

Gravity FreeBodySolver::gravity_at(double x_m) const {
    Gravity g;
    g.theta = frame_.slope_rad_at(x_m);
    g.cos_theta = std::cos(g.theta);
    g.sin_theta = std::sin(g.theta);
    g.gx = frame_.gravity_m_s2 * g.sin_theta;
    g.gy = -frame_.gravity_m_s2 * g.cos_theta;
    g.g_cos = -g.gy;
    return g;
}

double FreeBodySolver::stretch_cap_s() const {
    const double left = frame_.time_limit_s - t_;
    return frame_.curved() ? std::min(left, kCurvedStretchS) : left;
}

FreeBodySolver::Contact FreeBodySolver::contact(const State& s, Phase p, Vec2 r) const {
    Contact c;
    if (p != Phase::flight) {
        const double w2 = s.w * s.w;
        if (p == Phase::stick) {
            // The vertex stays put: both components of its acceleration vanish,
            // a_c + alpha x r - w^2 r = 0 with M a_c = M g + (F, N), I alpha = r x (F, N).
            const double k11 = inv_m_ + r.y * r.y * inv_i_, k12 = -r.x * r.y * inv_i_;
            const double k22 = inv_m_ + r.x * r.x * inv_i_;
            const double b1 = w2 * r.x - g_.gx, b2 = w2 * r.y - g_.gy;
            const double inv_det = 1.0 / (k11 * k22 - k12 * k12);
            c.F = (b1 * k22 - k12 * b2) * inv_det;
            c.N = (k11 * b2 - k12 * b1) * inv_det;
        } else {
            // The vertex slides along the ramp: only its normal acceleration vanishes, and friction
            // is mu N against the slip.
            const double f = -mu_ * slip_sign_;  // F = f N
            c.N = (w2 * r.y - g_.gy) / (inv_m_ + r.x * (r.x - f * r.y) * inv_i_);
            c.F = f * c.N;
        }
    }
    return c;
}

void FreeBodySolver::project(State& s, Phase p) const {
    // Puts the contact vertex exactly on the ramp (and at rest on it, sticking) as a stretch on it
    // begins: an event located to a nanosecond leaves it a rounding error off.
    if (p == Phase::flight) return;
    const Vec2 r = arm(on_, s.a);
    s.y = -r.y;
    s.vy = -s.w * r.x;
    if (p == Phase::stick) {
        s.x = pivot_x_ - r.x;
        s.vx = s.w * r.y;
    }
}

State FreeBodySolver::flight_at(const State& s, double tau, const Gravity& g) {
    return {s.x + s.vx * tau + 0.5 * g.gx * tau * tau, s.y + s.vy * tau + 0.5 * g.gy * tau * tau, s.a + s.w * tau,
            s.vx + g.gx * tau, s.vy + g.gy * tau, s.w};
}

double FreeBodySolver::event_value(const State& s, Phase p, Event e, Turn t, const Contact* c) const {
    constexpr double kNever = 1.0;
    switch (e) {
        case Event::touch:  // a neighbour of the contact vertex meeting the ramp
            return std::min(s.y + arm(on_ - 1, t).y, s.y + arm(on_ + 1, t).y);
        case Event::lift: return c ? c->N : contact(s, p, arm(on_, t)).N;
        case Event::slip: {
            if (p != Phase::stick) return kNever;
            const Contact f = c ? *c : contact(s, p, arm(on_, t));
            return mu_ * f.N - std::fabs(f.F);
        }
        case Event::grip:
            return p == Phase::slide ? vertex_velocity(s, arm(on_, t)).x * slip_sign_ : kNever;
        case Event::end: return frame_.end_centre_x_m - s.x;
        case Event::rest:
            return std::max(std::hypot(s.vx, s.vy), std::fabs(s.w) * radius_) - frame_.rest_speed_m_s;
        case Event::none: break;
    }
    return kNever;
}

TrajectorySample FreeBodySolver::sample(const State& s, double t) const {
    TrajectorySample r;
    r.time_s = t;
    r.position_m = s.x - start_x_;
    r.speed_m_s = s.vx;
    r.angle_deg = -(s.a - start_a_) * 180.0 / kPi;
    r.kinetic_J = 0.5 * m_ * (s.vx * s.vx + s.vy * s.vy) + 0.5 * inertia_ * s.w * s.w;
    r.potential_J = potential_J(s) - potential_offset_J_;
    r.dissipated_J = -(r.kinetic_J + r.potential_J);
    return r;
}

void FreeBodySolver::emit_rows_before(double t_end, std::function<State(double)> state_at) {
    for (;;) {
        const double ts = frame_.sample_time(next_row_);
        if (ts >= t_end) break;
        const State s = state_at(std::max(0.0, ts - t_));
        out_.measured.trajectory.push_back(sample(s, ts));
        out_.states.push_back({{s.a, {s.x, s.y}}, {s.vx, s.vy}, s.w});
        out_.landed_vertices.push_back(landed_);
        ++next_row_;
    }
    stretches_.push_back({t_, t_end, landed_, std::move(state_at)});
}

void FreeBodySolver::note_landing(long j, double kinetic_before_J) {
    if (j <= landed_) return;
    landed_ = j;
    FaceImpact f;
    f.index = static_cast<int>(out_.measured.impacts.size()) + 1;
    f.time_s = t_;
    f.position_m = s_.x - start_x_;
    f.kinetic_before_J = kinetic_before_J;
    f.kinetic_after_J = sample(s_, t_).kinetic_J;
    out_.measured.impacts.push_back(f);
}

void FreeBodySolver::finish(Behaviour b) {
    running_ = false;
    finished_ = true;
    Measurements& m = out_.measured;
    m.behaviour = b;
    m.end_time_s = t_;
    const TrajectorySample last = sample(s_, t_);
    m.distance_m = last.position_m;
    if (m.trajectory.empty() || m.trajectory.back().time_s < t_) {
        m.trajectory.push_back(last);
        out_.states.push_back({{s_.a, {s_.x, s_.y}}, {s_.vx, s_.vy}, s_.w});
        out_.landed_vertices.push_back(landed_);
    }
    if (b == Behaviour::rolled_to_end) set_terminal_velocity_at_end(m, n_, last);
}

void FreeBodySolver::stop_unsupported(const std::string& why) {
    running_ = false;
    out_.unsupported_time_s = t_;
    out_.unsupported_why = why;
}

void FreeBodySolver::impact(long j) {
    const double kinetic_before = sample(s_, t_).kinetic_J;
    const Vec2 r = arm(j, s_.a);
    const Vec2 v = vertex_velocity(s_, r);
    if (v.y < 0.0) {
        // Impulse P = (Pt, Pn) at the vertex: its velocity changes by K P. No bounce: the normal
        // velocity ends at zero; the tangential one too if |Pt| <= mu Pn, else Pt = -+mu Pn.
        const double k11 = 1.0 / m_ + r.y * r.y / inertia_, k12 = -r.x * r.y / inertia_;
        const double k22 = 1.0 / m_ + r.x * r.x / inertia_;
        const double det = k11 * k22 - k12 * k12;
        double pt = (-v.x * k22 + k12 * v.y) / det;
        double pn = (-k11 * v.y + k12 * v.x) / det;
        if (std::fabs(pt) > mu_ * pn) {
            const double sign = pt > 0.0 ? 1.0 : -1.0;
            pn = -v.y / (k22 + k12 * mu_ * sign);
            pt = sign * mu_ * pn;
        }
        s_.vx += pt / m_;
        s_.vy += pn / m_;
        s_.w += (r.x * pn - r.y * pt) / inertia_;
    }
    // The vertex that was on the ramp (if any) must not be driven into it by the impact: that is a
    // face set down flat on both its vertices, which this model leaves to Box2D.
    if (phase_ != Phase::flight && on_ != j) {
        const Vec2 ro = arm(on_, s_.a);
        if (s_.y + ro.y < 1e-6 && vertex_velocity(s_, ro).y < -1e-6) {
            stop_unsupported("a face set down on both its vertices at once");
            return;
        }
    }
    // The landing vertex itself: at a face's landing both its vertices are equally low.
    note_landing(j, kinetic_before);
    settle_on(j);
}

void FreeBodySolver::settle_on(long j) {
    on_ = j;
    const Vec2 r = arm(j, s_.a);
    const double vt = vertex_velocity(s_, r).x;
    // Below a micrometre per second the vertex has stopped along the ramp.
    if (std::fabs(vt) < 1e-6) {
        phase_ = Phase::stick;
        pivot_x_ = s_.x + r.x;
        project(s_, phase_);
        const Contact c = contact(s_, Phase::stick);
        if (c.N < 0.0) {
            phase_ = Phase::flight;
        } else if (std::fabs(c.F) > mu_ * c.N) {
            phase_ = Phase::slide;
            slip_sign_ = c.F > 0.0 ? -1 : 1;  // friction at its limit pushes the way it was needed
            ++out_.slides;
        }
    } else {
        phase_ = Phase::slide;
        slip_sign_ = vt > 0.0 ? 1 : -1;
        project(s_, phase_);
        ++out_.slides;
        if (contact(s_, Phase::slide).N < 0.0) phase_ = Phase::flight;
    }
    if (phase_ == Phase::flight) {
        ++out_.flights;
    }
}

State FreeBodySolver::on_vertex(long on, double c_phi, double s_phi, double x, double vx, double a, double w,
                                Turn& t) const {
    const Vec2 u = unit_[index(on)];  // a = phi - beta
    t = {c_phi * u.x + s_phi * u.y, s_phi * u.x - c_phi * u.y};
    return {x, -radius_ * s_phi, a, vx, -w * radius_ * c_phi, w};
}

State FreeBodySolver::stick_state(const PendulumSeries& ps, const Gravity& g, long on, double pivot_x, double psi0,
                                  double a0, double tau, Turn& t) const {
    double psi = 0.0, rate = 0.0, sin_psi = 0.0, cos_psi = 0.0;
    ps.psi_and_rate(tau, psi, rate);
    ps.sin_cos_psi(tau, sin_psi, cos_psi);
    // The contact vertex points along phi = psi + theta - pi/2 from the centre, and the centre is
    // where that puts the vertex on the pivot, moving about it.
    const double c_phi = sin_psi * g.cos_theta + cos_psi * g.sin_theta;
    const double s_phi = sin_psi * g.sin_theta - cos_psi * g.cos_theta;
    return on_vertex(on, c_phi, s_phi, pivot_x - radius_ * c_phi, rate * radius_ * s_phi, a0 + (psi - psi0), rate, t);
}

State FreeBodySolver::slide_state(const SlideSeries& ss, long on, double phi0, double a0, double tau, Turn& t) const {
    const SlideSeries::Point q = ss.at(tau);
    return on_vertex(on, q.cos_phi, q.sin_phi, q.x_m, q.vx_m_s, a0 + (q.phi - phi0), q.omega, t);
}

void FreeBodySolver::stick_stretch() {
    const double a0 = s_.a, psi0 = psi_of(a0);
    const auto ps = std::make_shared<const PendulumSeries>(psi0, s_.w, pendulum_a_);
    follow(Phase::stick, ps->accurate_step_s(),
           [this, ps, g = g_, on = on_, pivot_x = pivot_x_, psi0, a0](double tau, Turn& t) {
               return stick_state(*ps, g, on, pivot_x, psi0, a0, tau, t);
           });
}

void FreeBodySolver::slide_stretch() {
    const double a0 = s_.a, phi0 = beta_[index(on_)] + a0;
    SlideBody b;
    b.radius_m = radius_;
    b.inv_mass_per_kg = inv_m_;
    b.inv_inertia = inv_i_;
    b.friction_ratio = -mu_ * slip_sign_;
    b.gravity_along_m_s2 = g_.gx;
    b.gravity_normal_m_s2 = g_.g_cos;
    const auto ss = std::make_shared<const SlideSeries>(b, phi0, s_.w, s_.x, s_.vx);
    follow(Phase::slide, ss->accurate_step_s(), [this, ss, on = on_, phi0, a0](double tau, Turn& t) {
        return slide_state(*ss, on, phi0, a0, tau, t);
    });
}

template <class StateAt>
void FreeBodySolver::follow(Phase p, double span_s, StateAt state_at) {
    // Each event that holds at a grid point is traced back to where it began, and the earliest wins.
    const double span = std::min(span_s, stretch_cap_s());
    Turn turn0;
    State s0 = state_at(0.0, turn0);
    std::array<double, std::size(kContactEvents)> v0{};
    const Contact c0 = contact(s0, p, arm(on_, turn0));
    for (size_t k = 0; k < v0.size(); ++k) v0[k] = event_value(s0, p, kContactEvents[k], turn0, &c0);
    double lo = 0.0, tau = span;
    Event e = Event::none;
    auto event_at = [&](double x, Event ev) {
        Turn tx;
        const State sx = state_at(x, tx);
        return event_value(sx, p, ev, tx);
    };
    while (lo < span && e == Event::none) {
        const double h = std::min({kContactGridS, kContactTurnRad / std::max(std::fabs(s0.w), 1e-9), span - lo});
        const double hi = lo + h;
        ++out_.steps;
        Turn turn1;
        const State s1 = state_at(hi, turn1);
        std::array<double, std::size(kContactEvents)> v1{};
        const Contact c1 = contact(s1, p, arm(on_, turn1));
        for (size_t k = 0; k < v1.size(); ++k) {
            const Event ev = kContactEvents[k];
            v1[k] = event_value(s1, p, ev, turn1, &c1);
            // A shell rocking on the vertex passes through rest where it turns back; a grid point
            // either side of that can both be above the rest speed, so the turn itself is looked at.
            double end = hi, at_end = v1[k];
            if (ev == Event::rest && at_end > 0.0 && s0.w * s1.w < 0.0) {
                const double sign = s0.w > 0.0 ? 1.0 : -1.0;
                end = first_root(
                    [&](double x) {
                        Turn tx;
                        return sign * state_at(x, tx).w;
                    },
                    lo, sign * s0.w, hi, sign * s1.w, kEventTolS, out_.steps);
                at_end = event_at(end, ev);
            }
            if (at_end > 0.0) continue;
            // Coming to rest is slowing down through the rest speed, not starting from rest.
            if (ev == Event::rest && v0[k] <= 0.0) continue;
            const double when = v0[k] <= 0.0 ? lo
                                             : first_root([&](double x) { return event_at(x, ev); }, lo, v0[k], end,
                                                          at_end, kEventTolS, out_.steps);
            if (e == Event::none || when < tau) {
                e = ev;
                tau = when;
            }
        }
        if (e == Event::none) {
            lo = hi;
            s0 = s1;
            v0 = v1;
        }
    }
    if (e == Event::none) tau = span;
    emit_rows_before(t_ + tau, [state_at](double dt) {
        Turn unused;
        return state_at(dt, unused);
    });
    Turn unused;
    s_ = state_at(tau, unused);
    t_ += tau;
    after_contact_event(e);
}

void FreeBodySolver::after_contact_event(Event e) {
    switch (e) {
        case Event::touch: {
            // The lower neighbour (the event holds where its height reached zero, to rounding).
            const long j = arm(on_ + 1, s_.a).y < arm(on_ - 1, s_.a).y ? on_ + 1 : on_ - 1;
            s_.y -= s_.y + arm(j, s_.a).y;  // the halving leaves it a fraction of a nanometre in
            impact(j);
            break;
        }
        case Event::lift:
            phase_ = Phase::flight;
            ++out_.flights;
                break;
        case Event::slip: {
            const Contact c = contact(s_, Phase::stick);
            phase_ = Phase::slide;
            slip_sign_ = c.F > 0.0 ? -1 : 1;
            ++out_.slides;
            break;
        }
        case Event::grip: {
            // The slip has stopped: the vertex sticks where it is, if friction can hold it.
            const Vec2 r = arm(on_, s_.a);
            s_.vx = s_.w * r.y;  // the vertex at rest
            settle_on(on_);
            break;
        }
        case Event::end: finish(Behaviour::rolled_to_end); break;
        case Event::rest: stop_unsupported("the shell comes to rest on the ramp"); break;
        case Event::none:
            if (t_ >= frame_.time_limit_s) finish(Behaviour::time_limit);
            break;
    }
}

void FreeBodySolver::flight_stretch() {
    // The first touch of the ramp by the lowest vertex or a neighbour. Each vertex's height
    // h(tau) = y + vy tau - g cos(theta) tau^2 / 2 + R sin(beta + a + w tau) curves by at most
    // C = g cos(theta) + R w^2, so it stays above h + h' d - C d^2 / 2 over a step d, and its fourth
    // derivative is at most R w^4 in size (positive_for): the longer step either bound proves cannot
    // miss a touch. The fourth-order bound lets the search pass the vertex just left (rising as tau^3:
    // the normal force fell to zero smoothly) in a few steps where the second-order one crawled. A step
    // is never shorter than kFlightMinStepS, and one that ends with a vertex below the ramp is traced
    // back to the touch.
    // Steps are kept under half a face's turn, so no vertex but these three can come lowest within one.
    const State s0 = s_;
    const double curve = g_.g_cos + radius_ * s0.w * s0.w;
    const double d_turn = kPi / n_ / std::max(std::fabs(s0.w), 1e-9);
    // Cut short on a curved track: the flight goes on in the next stretch, gravity turned.
    const double left = stretch_cap_s();
    const bool cut = left < frame_.time_limit_s - t_;
    const double end_x = frame_.end_centre_x_m;
    // The lowest of the three vertices about the lowest one at tau: its height and index.
    auto lowest_of = [&](const State& s, long& which) {
        const long k = lowest(s.a);
        const Turn t = turn_of(s.a);
        double h_min = std::numeric_limits<double>::infinity();
        for (long j = k - 1; j <= k + 1; ++j) {
            const double h = s.y + arm(j, t).y;
            if (h < h_min) {
                h_min = h;
                which = j;
            }
        }
        return h_min;
    };
    double tau = 0.0, stop = left;
    long hit = 0;
    bool touched = false;
    while (tau < left) {
        if (++out_.steps > kMaxFreeBodySteps) return stop_unsupported("the flight search took too many steps");
        const State s = flight_at(s0, tau);
        const long k = lowest(s.a);
        double d = d_turn;
        const double w2 = s.w * s.w;
        const Turn t = turn_of(s.a);
        for (long j = k - 1; j <= k + 1; ++j) {
            const Vec2 r = arm(j, t);
            const double h = std::max(0.0, s.y + r.y), rate = s.vy + s.w * r.x;
            const double second = (rate + std::sqrt(rate * rate + 2.0 * curve * h)) / curve;
            const double fourth =
                positive_for(h, rate, -g_.g_cos - w2 * r.y, -w2 * s.w * r.x, w2 * w2 * radius_, d_turn);
            d = std::min(d, std::max(second, fourth));
        }
        const double next = std::min(tau + std::max(d, kFlightMinStepS), left);
        long j_next = 0;
        const double h_next = lowest_of(flight_at(s0, next), j_next);
        if (h_next < 0.0) {
            const double h_now = lowest_of(flight_at(s0, tau), j_next);
            const double hi = first_root([&](double dt) { return lowest_of(flight_at(s0, dt), j_next); }, tau,
                                         std::max(h_now, 1e-300), next, h_next, kEventTolS, out_.steps);
            lowest_of(flight_at(s0, hi), hit);
            stop = hi;
            touched = true;
            break;
        }
        if (flight_at(s0, next).x >= end_x) {
            stop = next;
            break;
        }
        tau = next;
    }
    // The ramp's end within the flight: the centre's x, monotonic down the ramp here.
    bool at_end = false;
    if (flight_at(s0, stop).x >= end_x) {
        stop = first_root([&](double dt) { return end_x - flight_at(s0, dt).x; }, 0.0, end_x - s0.x, stop,
                          end_x - flight_at(s0, stop).x, kEventTolS, out_.steps);
        at_end = true;
    }
    emit_rows_before(t_ + stop, [s0, g = g_](double dt) { return flight_at(s0, dt, g); });
    s_ = flight_at(s0, stop);
    t_ += stop;
    if (at_end) return finish(Behaviour::rolled_to_end);
    if (!touched) {
        if (!cut) finish(Behaviour::time_limit);
        return;
    }
    s_.y -= s_.y + arm(hit, s_.a).y;  // exactly on the ramp (the halving leaves it a femtometre in)
    impact(hit);
}

FreeBodyMotion FreeBodySolver::run() {
    // Taken over on the ramp (turning about its lowest vertex) or above it.
    const long j = lowest(s_.a);
    on_ = j;
    if (s_.y + arm(j, s_.a).y > kTouchM) {
        phase_ = Phase::flight;
        ++out_.flights;
    } else {
        phase_ = Phase::stick;  // so that a first impact sees no other vertex down
        settle_on(j);
    }
    while (running_) {
        if (out_.steps > kMaxFreeBodySteps) {
            stop_unsupported("more than two million steps");
            break;
        }
        if (t_ >= frame_.time_limit_s) {
            finish(Behaviour::time_limit);
            break;
        }
        const double t_before = t_;
        if (frame_.curved()) g_ = gravity_at(s_.x);
        if (phase_ == Phase::flight) flight_stretch();
        else if (phase_ == Phase::stick) stick_stretch();
        else slide_stretch();
        chatter_ = t_ - t_before < kChatterS ? chatter_ + 1 : 0;
        if (running_ && chatter_ > kMaxChatter) {
            stop_unsupported("the contact switches state again and again within a microsecond");
            break;
        }
        if (running_ && !(std::isfinite(s_.x) && std::isfinite(s_.y) && std::isfinite(s_.w)))
            stop_unsupported("the state is not a finite number");
    }
    if (out_.unsupported_time_s) out_.measured.behaviour = Behaviour::running;
    for (const TrajectorySample& s : out_.measured.trajectory)
        out_.measured.max_energy_gain_J = std::max(out_.measured.max_energy_gain_J, -s.dissipated_J);
    return out_;
}

std::optional<FreeBodyRow> FreeBodySolver::row_at_step(long step, double step_hz, long first_step) const {
    // As the rows of a run sampled at every step from first_step: the rows before each stretch's end,
    // then the end's own row if it finished; past its last row, the last row.
    auto row = [&](const State& s, double t, long landed) {
        return FreeBodyRow{{{s.a, {s.x, s.y}}, {s.vx, s.vy}, s.w}, sample(s, t), landed};
    };
    auto time_of = [step_hz](long k) { return static_cast<double>(first_step_at(k, step_hz, step_hz)) / step_hz; };
    const double last_end = stretches_.empty() ? t_ : stretches_.back().t_end;
    long k = step;
    if (!finished_) {
        while (k >= first_step && time_of(k) >= last_end) --k;
        if (k < first_step) return std::nullopt;
    }
    const double ts = time_of(k);
    const auto it = std::upper_bound(stretches_.begin(), stretches_.end(), ts,
                                     [](double t, const Stretch& st) { return t < st.t_end; });
    if (it == stretches_.end()) return row(s_, t_, landed_);
    return row(it->at(std::max(0.0, ts - it->t0)), ts, it->landed);
}

}  // namespace

FreeBodyMotion free_body_motion(const FreeBody& body, const RampFrame& frame, const FreeBodyStart& start) {
    const auto solver = std::make_shared<FreeBodySolver>(body, frame, start);
    FreeBodyMotion m = solver->run();
    m.row_at_step = [solver](long step, double step_hz, long first_step) {
        return solver->row_at_step(step, step_hz, first_step);
    };
    return m;
}

}  // namespace polyroll::models
