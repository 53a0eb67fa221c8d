// Timing a pivot's rotation from the energy integral: see face_clock.h.
#include "sim/models/face_clock.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "sim/geometry.h"

namespace polyroll::models {

namespace {

constexpr double kPi = geom::kPi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Quadrature orders available; the largest bounds how long an arc may be in u.
constexpr std::array<int, 8> kOrders = {3, 4, 6, 8, 12, 16, 24, 32};
// Gauss-Legendre's error on an integrand analytic inside the Bernstein ellipse of parameter rho is
// about rho^(-2 order): ln(1e16), so with a branch point's algebraic factor about 1e-15 is left.
constexpr double kLogTarget = 16.0 * 2.302585092994046;

struct Table {
    std::vector<double> nodes, weights;
    double min_rho = 0.0;  // the Bernstein parameter above which this order reaches the target
};

// Nodes and weights by Newton's method on the Legendre polynomial: computed once, exact to rounding.
Table legendre_table(int n) {
    Table t;
    t.nodes.resize(static_cast<size_t>(n));
    t.weights.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
        double dp = 1.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = x;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (x * p1 - p0) / (x * x - 1.0);
            const double dx = p1 / dp;
            x -= dx;
            if (std::fabs(dx) < 1e-16) break;
        }
        t.nodes[static_cast<size_t>(i)] = x;
        t.weights[static_cast<size_t>(i)] = 2.0 / ((1.0 - x * x) * dp * dp);
    }
    return t;
}

const std::array<Table, kOrders.size()>& tables() {
    static const std::array<Table, kOrders.size()> t = [] {
        std::array<Table, kOrders.size()> out;
        for (size_t i = 0; i < kOrders.size(); ++i) {
            out[i] = legendre_table(kOrders[i]);
            out[i].min_rho = std::exp(kLogTarget / (2.0 * kOrders[i]));
        }
        return out;
    }();
    return t;
}

const std::array<Table, kOrders.size()>& kTables = tables();

}  // namespace

EnergyArc::EnergyArc(double a, double c) : a_(a), A_(2.0 * (c - a)), B_(4.0 * a) {
    if (a_ > 0.0) {
        k_ = std::sqrt(std::fabs(A_) / B_);
        root_abs_a_ = std::sqrt(std::fabs(A_));
        dt_du_scale_ = 2.0 / std::sqrt(B_);
        // The weight is singular where |s| = 1: at u = +-U (real) and at +-U + i pi for A > 0
        // (sinh(u + i pi) = -sinh(u)); for A < 0 at +-U with cosh, and again at +-U + i pi.
        const double inv = 1.0 / k_;
        singular_u_ = A_ > 0.0 ? std::asinh(inv) : inv > 1.0 ? std::acosh(inv) : 0.0;
    }
}

bool EnergyArc::set_arc(double psi_from, double psi_to) {
    if (!(a_ > 0.0) || !(k_ > 0.0) || !(psi_to != psi_from)) return false;
    dir_ = psi_to > psi_from ? 1 : -1;
    const double s_from = std::sin(0.5 * psi_from), s_to = std::sin(0.5 * psi_to);
    if (A_ > 0.0) {
        u_from_ = std::asinh(s_from / k_);
        u_to_ = std::asinh(s_to / k_);
        u_sign_ = dir_;
    } else {
        // Below the top's energy: psi stays on one side of it, with |s| >= k; psi' = 0 where |s| = k.
        if (s_from * s_to <= 0.0) return false;
        branch_ = s_from > 0.0 ? 1.0 : -1.0;
        const double r_from = std::fabs(s_from) / k_, r_to = std::fabs(s_to) / k_;
        if (r_from < 1.0 || r_to <= 1.0) return false;  // a turning point at or before psi_to
        u_from_ = std::acosh(r_from);
        u_to_ = std::acosh(r_to);
        // Moving away from the top (|s| growing) u grows; towards it, a turning point comes first.
        if (u_to_ < u_from_) return false;
        u_sign_ = 1.0;
    }
    return std::isfinite(u_from_) && std::isfinite(u_to_) && !rule_for(u_from_, u_to_).nodes.empty();
}

ArcPoint EnergyArc::point(double u, bool with_angle) const {
    ArcPoint p;
    p.u = u;
    // sinh and cosh from one exponential: s only needs absolute accuracy (|s| <= 1).
    const double e = std::exp(u), half_e = 0.5 * e, half_inv = 0.5 / e;
    const double sh = half_e - half_inv, ch = half_e + half_inv;
    double s = 0.0;
    if (A_ > 0.0) {
        s = k_ * sh;
        p.rate_rad_s = dir_ * root_abs_a_ * ch;
    } else {
        s = branch_ * k_ * ch;
        p.rate_rad_s = dir_ * root_abs_a_ * std::fabs(sh);
    }
    s = std::clamp(s, -1.0, 1.0);
    const double cos_half = std::sqrt(1.0 - s * s);
    p.sin_psi = 2.0 * s * cos_half;
    p.cos_psi = 1.0 - 2.0 * s * s;
    p.psi_rad = with_angle ? 2.0 * std::asin(s) : 0.0;
    return p;
}

double EnergyArc::weight(double u) const {
    // sinh and cosh from one exponential: s only needs absolute accuracy (it is at most 1).
    const double e = std::exp(u), half_e = 0.5 * e, half_inv = 0.5 / e;
    const double s = k_ * (A_ > 0.0 ? half_e - half_inv : half_e + half_inv);
    return dt_du_scale_ / std::sqrt(1.0 - s * s);
}

// The Gauss-Legendre order comes from the Bernstein ellipse parameter rho of the weight's nearest
// singularity: the ellipse with foci at the arc's ends through it has semi-major axis (distance to one
// end + distance to the other) / 2, in units of half the arc, and rho = major + sqrt(major^2 - 1).
EnergyArc::Rule EnergyArc::rule_for(double u1, double u2) const {
    const double half = 0.5 * std::fabs(u2 - u1);
    if (!(half > 0.0) || !(singular_u_ > 0.0)) return {};
    // The nearer of the singular pairs is the one on the arc's side of u = 0, in units of half the arc.
    const double x = (singular_u_ - std::fabs(0.5 * (u1 + u2))) / half, y = kPi / half;
    if (!(x > 1.0)) return {};
    const double rho_real = x + std::sqrt(x * x - 1.0);
    const double major = 0.5 * (std::sqrt((x + 1.0) * (x + 1.0) + y * y) + std::sqrt((x - 1.0) * (x - 1.0) + y * y));
    const double rho = std::min(rho_real, major + std::sqrt(major * major - 1.0));
    for (const Table& t : kTables)
        if (rho >= t.min_rho) return {t.nodes, t.weights};
    return {};
}

double EnergyArc::time_s(double u1, double u2) const {
    if (u1 == u2) return 0.0;
    const Rule r = rule_for(u1, u2);
    if (r.nodes.empty()) return kNaN;
    const double mid = 0.5 * (u1 + u2), half = 0.5 * std::fabs(u2 - u1);
    double sum = 0.0;
    for (size_t i = 0; i < r.nodes.size(); ++i) sum += r.weights[i] * weight(mid + half * r.nodes[i]);
    return half * sum;
}

double EnergyArc::u_after(double u1, double tau) const {
    const double lo = std::min(u_from_, u_to_), hi = std::max(u_from_, u_to_);
    // du/dt = u_sign / weight(u): a second-order step, then Newton on the time.
    const double w1 = weight(u1);
    const double e = std::exp(u1), sh = 0.5 * (e - 1.0 / e), ch = 0.5 * (e + 1.0 / e);
    const double s1 = A_ > 0.0 ? k_ * sh : k_ * ch;
    const double ds_du = A_ > 0.0 ? k_ * ch : k_ * sh;
    // d(1/weight)/du = -s ds/du / (1 - s^2) / dt_du_scale
    const double dinv = -s1 * ds_du / (1.0 - s1 * s1) / dt_du_scale_ * (dt_du_scale_ / w1);
    const double v = u_sign_ / w1;
    double u = std::clamp(u1 + v * tau + 0.5 * dinv * v * u_sign_ * tau * tau, lo, hi);
    // Each iteration times only the stretch from the previous iterate (short, so a low order), and
    // stops after a correction below 1e-6: Newton converges quadratically, and with dt/du varying by
    // less than a factor 2 over the arc the error left is below 1e-12.
    double t_at_u = u_sign_ * (u >= u1 ? 1.0 : -1.0) * time_s(u1, u);
    for (int it = 0; it < 20 && std::isfinite(t_at_u); ++it) {
        const double next = std::clamp(u - u_sign_ * (t_at_u - tau) / weight(u), lo, hi);
        const double step = next - u;
        if (std::fabs(step) <= 1e-6 * std::max(1.0, std::fabs(u))) return next;
        t_at_u += u_sign_ * (step > 0.0 ? 1.0 : -1.0) * time_s(u, next);
        u = next;
    }
    return u;
}

}  // namespace polyroll::models
