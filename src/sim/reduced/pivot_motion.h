// Rotation about a pivot vertex between impacts. A rigid body turning about a fixed point under
// gravity is an inverted pendulum: with psi the body's rotation past the position where its centre of
// mass stands straight above the pivot, psi'' = a sin(psi), a = M g d / I_pivot. This file is that
// equation's right-hand side for the Taylor series integrator (taylor_series.h).
#pragma once

#include <limits>

#include "sim/reduced/taylor_series.h"

namespace polyroll::models {

class PendulumSeries {
public:
    // The series of psi(t0 + tau) from psi(t0) = psi0, psi'(t0) = rate0. Given the step the caller
    // wants (where it expects the next event), it stops at the lowest order accurate over that step
    // (kTruncationRad; Jorba and Zou's choice of order): a short step, as a many-sided polygon's
    // face, needs far fewer terms than the longest accurate one.
    PendulumSeries(double psi0, double rate0_rad_s, double a_per_s2,
                   double want_step_s = std::numeric_limits<double>::infinity());

    double psi(double tau_s) const { return value_at(x_, tau_s, order_); }
    double rate(double tau_s) const { return value_at(r_, tau_s, order_); }  // psi'
    // psi' and psi'' = a sin(psi), in one pass.
    void rate_and_acceleration(double tau_s, double& rate, double& acceleration) const {
        rate = value_at(r_, tau_s, order_);
        acceleration = a_ * cos_sin_at(e_, tau_s, order_)[1];
    }
    void psi_and_rate(double tau_s, double& psi, double& rate) const { values_at(x_, r_, tau_s, psi, rate, order_); }
    // sin(psi(t)) and cos(psi(t)) from their own series: no trigonometry.
    void sin_cos_psi(double tau_s, double& sin_psi, double& cos_psi) const {
        const CosSin v = cos_sin_at(e_, tau_s, order_);
        sin_psi = v[1];
        cos_psi = v[0];
    }
    // The step the series is accurate over: the step wanted where a lower order reached it, else the
    // whole order's (accurate_step_s, which may pass the step wanted: the caller caps it).
    double accurate_step_s() const { return step_s_; }
    int order() const { return order_; }

private:
    double a_ = 0.0;
    int order_ = kSeriesOrder;
    double step_s_ = 0.0;
    Series x_{}, r_{};  // psi and psi'
    CosSinSeries e_{};  // cos(psi) and sin(psi)
};

}  // namespace polyroll::models
