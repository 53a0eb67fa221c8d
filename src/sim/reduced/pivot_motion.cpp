// The inverted pendulum's series: see pivot_motion.h.
#include "sim/reduced/pivot_motion.h"

#include <cmath>

namespace polyroll::models {

namespace {
// The lowest order a series stops at: its last two terms then say how fast the terms fall.
constexpr int kMinOrder = 4;
}  // namespace

PendulumSeries::PendulumSeries(double psi0, double rate0, double a, double want_step_s) : a_(a) {
    // psi' = r and r' = a sin(psi) give psi's and r's coefficient k + 1 from r's and the sine's
    // coefficient k, and the sine's and cosine's next coefficients follow from r's (taylor_series.h).
    constexpr int N = kSeriesOrder;
    x_[0] = psi0;
    r_[0] = rate0;
    e_[0] = CosSin{std::cos(psi0), std::sin(psi0)};
    // psi's terms at the end of the step wanted, the power of the step kept as the order grows.
    const bool wants = want_step_s < std::numeric_limits<double>::infinity();
    double step_power = 1.0, last_term = std::numeric_limits<double>::infinity();
    for (int k = 0; k < N; ++k) {
        const auto kk = static_cast<size_t>(k);
        x_[kk + 1] = r_[kk] * kInverse[kk + 1];
        r_[kk + 1] = a * e_[kk][1] * kInverse[kk + 1];
        cos_sin_coefficient(r_, e_, k + 1);
        if (!wants) continue;
        step_power *= want_step_s;
        const double term = std::fabs(x_[kk + 1]) * step_power;
        // Both last terms: odd or even ones vanish in symmetric cases.
        if (k + 1 >= kMinOrder && term <= kTruncationRad && last_term <= kTruncationRad) {
            order_ = k + 1;
            step_s_ = want_step_s;
            return;
        }
        last_term = term;
    }
    step_s_ = models::accurate_step_s(x_);
}

}  // namespace polyroll::models
