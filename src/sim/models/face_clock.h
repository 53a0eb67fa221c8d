// The time a pivot's rotation takes, from the energy integral instead of stepping. Between impacts
// the body turns about a fixed vertex as the inverted pendulum psi'' = a sin(psi) (pivot_motion.h),
// whose energy c = psi'^2 / 2 + a cos(psi) is conserved: the fill is frozen between impacts in both
// reduced models and nothing dissipates there. So psi'^2 = A + B s^2 with s = sin(psi / 2),
// A = 2 (c - a), B = 4 a, and turning from psi_1 to psi_2 takes t = integral dpsi / |psi'|.
//
// That integrand blows up at a turning point (psi' = 0) and nearly so when the body barely makes it
// over the top (A small), which ruins plain quadrature. The substitution s = k sinh(u) (A > 0,
// k = sqrt(A / B)) or s = +-k cosh(u) (A < 0, k = sqrt(-A / B)) removes both: psi' = sqrt|A| cosh(u)
// or sqrt|A| |sinh(u)|, and dt = (2 / sqrt(B)) du / sqrt(1 - s^2), smooth and between 1 and 2 on every
// arc a polygon of 3 or more sides turns through. Gauss-Legendre quadrature in u, with the order
// chosen from how far the integrand's nearest singularity (s = +-1) lies from the arc (its Bernstein
// ellipse), then gives the time to about 1e-15.
#pragma once

#include <span>

namespace polyroll::models {

// A point of the motion, in u and in the rotation.
struct ArcPoint {
    double u = 0.0;
    double psi_rad = 0.0, sin_psi = 0.0, cos_psi = 1.0;
    double rate_rad_s = 0.0;  // psi', signed
};

class EnergyArc {
public:
    // a = M g d / I_pivot (1/s^2); c = psi'^2 / 2 + a cos(psi) (1/s^2).
    EnergyArc(double a_per_s2, double c_per_s2);

    // Sets the arc from psi_from to psi_to, turning that way (psi' keeps one sign on it). False if
    // this arc cannot be timed here: no gravity, the top reached exactly (A = 0), psi' vanishing
    // before psi_to (a turning point: the body swings back), or psi_from and psi_to on opposite sides
    // of the top with A < 0.
    bool set_arc(double psi_from_rad, double psi_to_rad);
    double u_from() const { return u_from_; }
    double u_to() const { return u_to_; }

    // The point at u; psi_rad itself (an arcsine) only if with_angle.
    ArcPoint point(double u, bool with_angle = true) const;
    // The time from u_1 to u_2 on the arc (positive either way). NaN if no rule reaches 1e-15.
    double time_s(double u_1, double u_2) const;
    // The point a time tau_s after u_1 along the arc (Newton's method on time_s, from a second-order
    // step), clamped to the arc.
    double u_after(double u_1, double tau_s) const;
    // The Gauss-Legendre nodes of the rule time_s(u_from, u_to) uses, as points, for checks along
    // the arc (the normal force).
    template <class F>
    void for_each_node(F f) const;

private:
    struct Rule {
        std::span<const double> nodes, weights;
    };
    Rule rule_for(double u_1, double u_2) const;
    double weight(double u) const;  // dt/du

    double a_ = 0.0, A_ = 0.0, B_ = 0.0, k_ = 0.0, root_abs_a_ = 0.0, dt_du_scale_ = 0.0;
    double singular_u_ = 0.0;  // |u| where |s| = 1 (0: none, A < 0 with k >= 1)
    double branch_ = 1.0;  // A < 0: the sign of s on the arc
    int dir_ = 1;          // the sign of psi'
    double u_sign_ = 1.0;  // the sign of du/dt
    double u_from_ = 0.0, u_to_ = 0.0;
};

template <class F>
void EnergyArc::for_each_node(F f) const {
    const Rule r = rule_for(u_from_, u_to_);
    const double mid = 0.5 * (u_from_ + u_to_), half = 0.5 * (u_to_ - u_from_);
    for (double x : r.nodes) f(point(mid + half * x, false));
}

}  // namespace polyroll::models
