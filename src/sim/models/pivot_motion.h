// Rotation about a pivot vertex between impacts. A rigid body turning about a fixed point under
// gravity is an inverted pendulum: with psi the body's rotation past the position where its centre of
// mass stands straight above the pivot, psi'' = a sin(psi), a = M g d / I_pivot. This file is that
// equation's right-hand side for the Taylor series integrator (taylor_series.h).
#pragma once

#include "sim/models/taylor_series.h"

namespace polyroll::models {

class PendulumSeries {
public:
    // The series of psi(t0 + tau) from psi(t0) = psi0, psi'(t0) = rate0.
    PendulumSeries(double psi0, double rate0_rad_s, double a_per_s2);

    double psi(double tau_s) const { return value_at(x_, tau_s); }
    double rate(double tau_s) const { return derivative_at(x_, tau_s); }  // psi'
    void psi_and_rate(double tau_s, double& psi, double& rate) const { value_and_derivative_at(x_, tau_s, psi, rate); }
    // sin(psi(t)) and cos(psi(t)) from their own series: no trigonometry.
    void sin_cos_psi(double tau_s, double& sin_psi, double& cos_psi) const {
        sin_psi = value_at(s_, tau_s);
        cos_psi = value_at(c_, tau_s);
    }
    double accurate_step_s() const { return models::accurate_step_s(x_); }

private:
    Series x_{}, s_{}, c_{};
};

}  // namespace polyroll::models
