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
constexpr std::size_t at(int k) { return static_cast<std::size_t>(k); }
}  // namespace detail

// Horner's rule on a polynomial of degree `order` in two interleaved halves: the even and the odd
// coefficients, each in tau^2, so each half waits on half as many multiply-adds (the dense output's
// evaluations are chains of dependent operations, not short of arithmetic units). T is a number or
// a CosSin pair.
template <class T, std::size_t M>
inline T horner_at(const std::array<T, M>& x, double tau_s, int order) {
    const double tau2 = tau_s * tau_s;
    const int top_even = order - order % 2, top_odd = order - 1 + order % 2;
    T even = x[detail::at(top_even)];
    T odd = top_odd >= 1 ? x[detail::at(top_odd)] : T{};
    for (int k = top_even - 2; k >= 0; k -= 2) even = even * tau2 + x[detail::at(k)];
    for (int k = top_odd - 2; k >= 1; k -= 2) odd = odd * tau2 + x[detail::at(k)];
    return even + odd * tau_s;
}

// The series' value at tau, truncated at `order` (a series built to a lower order has no higher terms).
inline double value_at(const Series& x, double tau_s, int order = kSeriesOrder) { return horner_at(x, tau_s, order); }

// 1/k for k >= 1: the recurrences divide by k on their critical path, where a multiplication is a
// fraction of a division's latency.
inline constexpr std::array<double, kSeriesOrder + 1> kInverse = [] {
    std::array<double, kSeriesOrder + 1> r{};
    for (int k = 1; k <= kSeriesOrder; ++k) r[detail::at(k)] = 1.0 / k;
    return r;
}();

// Two series' values at tau (a quantity and its rate, each kept as its own series).
inline void values_at(const Series& x, const Series& y, double tau_s, double& x_value, double& y_value,
                      int order = kSeriesOrder) {
    x_value = horner_at(x, tau_s, order);
    y_value = horner_at(y, tau_s, order);
}

// Coefficient k of the product of a and b, both known up to k. Four partial sums: with one, each
// term would wait for the previous addition (the recurrences' inner loop).
inline double product_coefficient(const Series& a, const Series& b, int k) {
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    int i = 0;
    for (; i + 3 <= k; i += 4) {
        s0 += a[detail::at(i)] * b[detail::at(k - i)];
        s1 += a[detail::at(i + 1)] * b[detail::at(k - i - 1)];
        s2 += a[detail::at(i + 2)] * b[detail::at(k - i - 2)];
        s3 += a[detail::at(i + 3)] * b[detail::at(k - i - 3)];
    }
    for (; i <= k; ++i) s0 += a[detail::at(i)] * b[detail::at(k - i)];
    return (s0 + s1) + (s2 + s3);
}

// The series of cos(x) and sin(x) side by side, coefficient by coefficient: each multiply-add of the
// recurrence and of Horner's rule on a pair is one vector operation (GCC's and Clang's vector
// extension), half the work of two series. [0] is the cosine, [1] the sine.
using CosSin = double __attribute__((vector_size(2 * sizeof(double))));
using CosSinSeries = std::array<CosSin, kSeriesOrder + 1>;

inline CosSin cos_sin_at(const CosSinSeries& e, double tau_s, int order = kSeriesOrder) {
    return horner_at(e, tau_s, order);
}

// Coefficient k >= 1 of cos(x) and sin(x), given the series of x' up to k - 1 and both up to k - 1:
// (sin x)' = cos(x) x' and (cos x)' = -sin(x) x', so k S_k = (x' C)_(k-1) and k C_k = -(x' S)_(k-1).
// Four partial sums, as in product_coefficient.
inline void cos_sin_coefficient(const Series& x_rate, CosSinSeries& e, int k) {
    CosSin s0 = {0.0, 0.0}, s1 = {0.0, 0.0}, s2 = {0.0, 0.0}, s3 = {0.0, 0.0};
    int i = 0;
    for (; i + 3 <= k - 1; i += 4) {
        s0 += x_rate[detail::at(i)] * e[detail::at(k - 1 - i)];
        s1 += x_rate[detail::at(i + 1)] * e[detail::at(k - 2 - i)];
        s2 += x_rate[detail::at(i + 2)] * e[detail::at(k - 3 - i)];
        s3 += x_rate[detail::at(i + 3)] * e[detail::at(k - 4 - i)];
    }
    for (; i <= k - 1; ++i) s0 += x_rate[detail::at(i)] * e[detail::at(k - 1 - i)];
    const CosSin sum = ((s0 + s1) + (s2 + s3)) * kInverse[detail::at(k)];  // (x' C, x' S)_(k-1) / k
    e[detail::at(k)] = CosSin{-sum[1], sum[0]};
}

// The size an angle's last two terms (radians) may have at the end of a step for a series truncated
// below kSeriesOrder (the step a motion asks for): the terms fall geometrically there, so what is
// neglected is smaller still, as accurate as accurate_step_s's steps.
constexpr double kTruncationRad = 1e-15;

// The step over which the series of an angle (radians) stays accurate to about 1e-16: a fifth of the
// radius of convergence its last two coefficients estimate, so the first neglected term is near 0.2^21
// of the coefficients' scale. Both are looked at because odd or even coefficients vanish in symmetric
// cases. Infinite if both are zero (an equilibrium).
double accurate_step_s(const Series& angle);

}  // namespace polyroll::models
