// The one integrator of the rigid polygon's motions between events: truncated Taylor series found
// by automatic differentiation (each coefficient from the lower ones through the equation of motion),
// whose polynomial is also the dense output for samples and for locating events, with an error per
// step near rounding. A motion supplies its right-hand side as a recurrence over these series, built
// from the operations below (pivot_motion.h: the pendulum about a sticking vertex; slide_motion.h: a
// sliding vertex); flight needs none, being a parabola.
#pragma once

#include <array>
#include <cstddef>

namespace polyroll::models {

constexpr int kSeriesOrder = 20;

// Coefficient k of a quantity's series in the time tau since the series began.
using Series = std::array<double, kSeriesOrder + 1>;

// Inline: these are the inner loops of every step and every event search.
namespace detail {
inline std::size_t at(int k) { return static_cast<std::size_t>(k); }
}  // namespace detail

// The series' value at tau (Horner).
inline double value_at(const Series& x, double tau_s) {
    double v = x[kSeriesOrder];
    for (int k = kSeriesOrder - 1; k >= 0; --k) v = v * tau_s + x[detail::at(k)];
    return v;
}

// Its derivative at tau, from the derivative's own coefficients.
inline double derivative_at(const Series& x, double tau_s) {
    double v = kSeriesOrder * x[kSeriesOrder];
    for (int k = kSeriesOrder - 1; k >= 1; --k) v = v * tau_s + k * x[detail::at(k)];
    return v;
}

// Both in one Horner pass (the derivative rounded differently from derivative_at's).
inline void value_and_derivative_at(const Series& x, double tau_s, double& value, double& derivative) {
    value = x[kSeriesOrder];
    derivative = 0.0;
    for (int k = kSeriesOrder - 1; k >= 0; --k) {
        derivative = derivative * tau_s + value;
        value = value * tau_s + x[detail::at(k)];
    }
}

// Coefficient k of the product of a and b, both known up to k.
inline double product_coefficient(const Series& a, const Series& b, int k) {
    double s = 0.0;
    for (int i = 0; i <= k; ++i) s += a[detail::at(i)] * b[detail::at(k - i)];
    return s;
}

// Coefficient k >= 1 of sin(x) and cos(x), given x up to k and both up to k - 1:
// (sin x)' = cos(x) x' and (cos x)' = -sin(x) x'.
inline void sin_cos_coefficient(const Series& x, Series& sin_x, Series& cos_x, int k) {
    // k S_k = sum_j j x_j C_(k-j) and k C_k = -sum_j j x_j S_(k-j), j = 1..k.
    double s = 0.0, c = 0.0;
    for (int j = 1; j <= k; ++j) {
        const double jx = j * x[detail::at(j)];
        s += jx * cos_x[detail::at(k - j)];
        c -= jx * sin_x[detail::at(k - j)];
    }
    sin_x[detail::at(k)] = s / k;
    cos_x[detail::at(k)] = c / k;
}

// The step over which the series of an angle (radians) stays accurate to about 1e-16: a fifth of the
// radius of convergence its last two coefficients estimate, so the first neglected term is near 0.2^21
// of the coefficients' scale. Both are looked at because odd or even coefficients vanish in symmetric
// cases. Infinite if both are zero (an equilibrium).
double accurate_step_s(const Series& angle);

}  // namespace polyroll::models
