// The inverted pendulum's series: see pivot_motion.h.
#include "sim/models/pivot_motion.h"

#include <cmath>

namespace polyroll::models {

PendulumSeries::PendulumSeries(double psi0, double rate0, double a) {
    // psi'' = a sin(psi) gives psi's coefficient k + 2 from the sine's coefficient k, and the sine's
    // and cosine's next coefficients follow from psi's (taylor_series.h).
    constexpr int N = kSeriesOrder;
    x_[0] = psi0;
    x_[1] = rate0;
    s_[0] = std::sin(psi0);
    c_[0] = std::cos(psi0);
    for (int k = 0; k < N; ++k) {
        const auto kk = static_cast<size_t>(k);
        if (k + 2 <= N) x_[kk + 2] = a * s_[kk] / ((k + 1.0) * (k + 2.0));
        sin_cos_coefficient(x_, s_, c_, k + 1);
    }
}

}  // namespace polyroll::models
