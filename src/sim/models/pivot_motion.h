// Rotation about a pivot vertex between impacts. A rigid body turning about a fixed point under
// gravity is an inverted pendulum: with psi the body's rotation past the position where its centre of
// mass stands straight above the pivot, psi'' = a sin(psi), a = M g d / I_pivot. This file integrates
// that equation with a high-order Taylor series, whose polynomial also serves as dense output for
// samples and for locating impacts, and whose error per step is near rounding.
#pragma once

#include <array>

namespace polyroll::models {

// The step over which a Taylor series of order kOrder with these last two coefficients (of the angle,
// in radians) stays accurate to about 1e-16: a fifth of the radius of convergence they estimate, so
// the first neglected term is near 0.2^21 of the coefficients' scale. Both are looked at because odd
// or even coefficients vanish in symmetric cases. Infinite if both are zero (an equilibrium).
double accurate_series_step_s(double second_last, double last, int order);

class PendulumSeries {
public:
    static constexpr int kOrder = 20;

    // The series of psi(t0 + tau) from psi(t0) = psi0, psi'(t0) = rate0.
    PendulumSeries(double psi0, double rate0_rad_s, double a_per_s2);

    double psi(double tau_s) const;
    double rate(double tau_s) const;      // psi'
    void psi_and_rate(double tau_s, double& psi, double& rate) const;
    // sin(psi(t)) and cos(psi(t)) from their own series: no trigonometry.
    void sin_cos_psi(double tau_s, double& sin_psi, double& cos_psi) const;
    // The first tau in [lo, hi] with psi(tau) = target, given that psi - target changes sign over
    // [lo, hi]: Newton's method kept inside a shrinking bracket.
    double solve_psi(double target, double lo, double hi) const;
    // The same for psi'(tau) = 0 (a turning point).
    double solve_turn(double lo, double hi) const;
    // The step over which the truncated series stays accurate to about 1e-16 rad: a fraction of the
    // radius of convergence estimated from the last coefficients. Infinite at an equilibrium.
    double accurate_step_s() const;

private:
    double a_ = 0.0;
    std::array<double, kOrder + 1> x_{}, s_{}, c_{};
};

}  // namespace polyroll::models
