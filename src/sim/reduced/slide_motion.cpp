// The sliding vertex's series: see slide_motion.h.
#include "sim/reduced/slide_motion.h"

#include <cmath>

namespace polyroll::models {

SlideSeries::SlideSeries(const SlideBody& b, double phi0, double omega0, double x0, double vx0) {
    constexpr int K = kSeriesOrder;
    const double r = b.radius_m, f = b.friction_ratio;
    Series w2{}, q{}, d{}, u{}, n{}, alpha{}, ax{};
    phi_[0] = phi0;
    omega_[0] = omega0;
    CosSinSeries e{};
    e[0] = CosSin{std::cos(phi0), std::sin(phi0)};
    sin_[0] = e[0][1];
    cos_[0] = e[0][0];
    x_[0] = x0;
    vx_[0] = vx0;
    for (int k = 0; k <= K; ++k) {
        const auto kk = static_cast<size_t>(k);
        if (k > 0) {
            // Each quantity's coefficient k from the derivative's coefficient k - 1.
            phi_[kk] = omega_[kk - 1] * kInverse[kk];
            omega_[kk] = alpha[kk - 1] * kInverse[kk];
            x_[kk] = vx_[kk - 1] * kInverse[kk];
            vx_[kk] = ax[kk - 1] * kInverse[kk];
            cos_sin_coefficient(omega_, e, k);
            cos_[kk] = e[kk][0];
            sin_[kk] = e[kk][1];
        }
        w2[kk] = product_coefficient(omega_, omega_, k);
        q[kk] = cos_[kk] - f * sin_[kk];
        d[kk] = (k == 0 ? b.inv_mass_per_kg : 0.0) + r * r * b.inv_inertia * product_coefficient(cos_, q, k);
        u[kk] = r * product_coefficient(sin_, w2, k) + (k == 0 ? b.gravity_normal_m_s2 : 0.0);
        // n d = u, coefficient by coefficient.
        double nd = 0.0;
        for (int i = 0; i < k; ++i) nd += n[static_cast<size_t>(i)] * d[static_cast<size_t>(k - i)];
        n[kk] = (u[kk] - nd) / d[0];
        alpha[kk] = r * b.inv_inertia * product_coefficient(n, q, k);
        ax[kk] = (k == 0 ? b.gravity_along_m_s2 : 0.0) + f * b.inv_mass_per_kg * n[kk];
    }
}

SlideSeries::Point SlideSeries::at(double tau) const {
    return {value_at(phi_, tau), value_at(omega_, tau), value_at(sin_, tau),
            value_at(cos_, tau), value_at(x_, tau),     value_at(vx_, tau)};
}

}  // namespace polyroll::models
