// The Taylor series of the inverted pendulum: see pivot_motion.h.
#include "sim/models/pivot_motion.h"

#include <cmath>
#include <limits>
#include <utility>

namespace polyroll::models {

namespace {
// Step = this share of the estimated radius of convergence: the first neglected term is then about
// 0.2^21 = 2e-15 of the coefficients' scale (radians), so a whole ramp of a few hundred steps keeps
// its energy to about 1e-13.
constexpr double kStepShare = 0.2;
constexpr int N = PendulumSeries::kOrder;
using Coefficients = std::array<double, N + 1>;

double horner(const Coefficients& c, double tau) {
    double v = c[N];
    for (int k = N - 1; k >= 0; --k) v = v * tau + c[static_cast<size_t>(k)];
    return v;
}

// Bracketed Newton iteration for f(tau) = 0 with f(lo), f(hi) of opposite signs (or one zero).
template <class F>
double bracketed_newton(F f, double lo, double hi) {
    double flo, dlo, fhi, dhi;
    f(lo, flo, dlo);
    f(hi, fhi, dhi);
    if (flo == 0.0) return lo;
    if (fhi == 0.0) return hi;
    const bool rising = fhi > 0.0;
    // Start from the secant: the functions here are smooth and nearly linear over a bracket.
    double x = lo + (hi - lo) * flo / (flo - fhi);
    for (int it = 0; it < 100; ++it) {
        double fx, dx;
        f(x, fx, dx);
        if (fx == 0.0) return x;
        ((fx > 0.0) == rising ? hi : lo) = x;
        double next = dx != 0.0 ? x - fx / dx : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        const double tiny = 2.0 * std::numeric_limits<double>::epsilon() * std::max(std::fabs(lo), std::fabs(hi));
        if (std::fabs(next - x) <= tiny || hi - lo <= tiny) return next;
        x = next;
    }
    return x;
}
}  // namespace

PendulumSeries::PendulumSeries(double psi0, double rate0, double a) : a_(a) {
    // Automatic differentiation of psi'' = a sin(psi): with S = sin(psi), C = cos(psi),
    // S' = C psi' and C' = -S psi' give k S_k = sum_j j x_j C_(k-j) and k C_k = -sum_j j x_j S_(k-j).
    x_[0] = psi0;
    x_[1] = rate0;
    s_[0] = std::sin(psi0);
    c_[0] = std::cos(psi0);
    std::array<double, N + 1> jx{};  // j x_j, filled as the x_j become known
    jx[1] = rate0;
    for (int k = 0; k < N; ++k) {
        if (k + 2 <= N) {
            x_[(static_cast<size_t>(k) + 2)] = a * s_[static_cast<size_t>(k)] / ((k + 1.0) * (k + 2.0));
            jx[(static_cast<size_t>(k) + 2)] = (k + 2) * x_[(static_cast<size_t>(k) + 2)];
        }
        const int m = k + 1;
        double ss = 0.0, cc = 0.0;
        for (int j = 1; j <= m; ++j) {
            ss += jx[static_cast<size_t>(j)] * c_[static_cast<size_t>(m - j)];
            cc -= jx[static_cast<size_t>(j)] * s_[static_cast<size_t>(m - j)];
        }
        s_[static_cast<size_t>(m)] = ss / m;
        c_[static_cast<size_t>(m)] = cc / m;
    }
}

double PendulumSeries::psi(double tau) const { return horner(x_, tau); }

double PendulumSeries::rate(double tau) const {
    double v = N * x_[N];
    for (int k = N - 1; k >= 1; --k) v = v * tau + k * x_[static_cast<size_t>(k)];
    return v;
}

void PendulumSeries::psi_and_rate(double tau, double& p, double& r) const {
    // Horner for the value and its derivative in one pass.
    p = x_[N];
    r = 0.0;
    for (int k = N - 1; k >= 0; --k) {
        r = r * tau + p;
        p = p * tau + x_[static_cast<size_t>(k)];
    }
}

void PendulumSeries::sin_cos_psi(double tau, double& s, double& c) const {
    s = s_[N];
    c = c_[N];
    for (int k = N - 1; k >= 0; --k) {
        s = s * tau + s_[static_cast<size_t>(k)];
        c = c * tau + c_[static_cast<size_t>(k)];
    }
}

double PendulumSeries::solve_psi(double target, double lo, double hi) const {
    return bracketed_newton(
        [&](double t, double& f, double& d) {
            psi_and_rate(t, f, d);
            f -= target;
        },
        lo, hi);
}

double PendulumSeries::solve_turn(double lo, double hi) const {
    // psi'' = a sin(psi): the derivative of the rate comes from the sine's series.
    return bracketed_newton(
        [&](double t, double& f, double& d) {
            double s, c;
            sin_cos_psi(t, s, c);
            (void)c;
            f = rate(t);
            d = a_ * s;
        },
        lo, hi);
}

double accurate_series_step_s(double second_last, double last, int order) {
    double rho = std::numeric_limits<double>::infinity();
    for (const auto& [c, k] : {std::pair{std::fabs(second_last), order - 1}, std::pair{std::fabs(last), order}})
        if (c > 0.0) rho = std::min(rho, std::pow(c, -1.0 / k));
    return kStepShare * rho;
}

double PendulumSeries::accurate_step_s() const { return accurate_series_step_s(x_[N - 1], x_[N], N); }

}  // namespace polyroll::models
