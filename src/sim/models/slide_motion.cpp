// The sliding vertex's Taylor series: see slide_motion.h.
#include "sim/models/slide_motion.h"

#include <cmath>

#include "sim/models/pivot_motion.h"

namespace polyroll::models {

namespace {
constexpr int K = SlideSeries::kOrder;

// Coefficient k of the product of two series known up to k.
template <class A, class B>
double product(const A& a, const B& b, int k) {
    double s = 0.0;
    for (int i = 0; i <= k; ++i) s += a[static_cast<size_t>(i)] * b[static_cast<size_t>(k - i)];
    return s;
}
}  // namespace

SlideSeries::SlideSeries(const SlideBody& b, double phi0, double omega0, double x0, double vx0) {
    const double r = b.radius_m, f = b.friction_ratio;
    std::array<double, K + 1> w2{}, q{}, d{}, u{}, n{}, alpha{}, ax{};
    phi_[0] = phi0;
    omega_[0] = omega0;
    sin_[0] = std::sin(phi0);
    cos_[0] = std::cos(phi0);
    x_[0] = x0;
    vx_[0] = vx0;
    for (int k = 0; k <= K; ++k) {
        const auto kk = static_cast<size_t>(k);
        if (k > 0) {
            // Each quantity's coefficient k from the derivative's coefficient k - 1.
            phi_[kk] = omega_[kk - 1] / k;
            omega_[kk] = alpha[kk - 1] / k;
            x_[kk] = vx_[kk - 1] / k;
            vx_[kk] = ax[kk - 1] / k;
            // (sin phi)' = cos(phi) phi' and (cos phi)' = -sin(phi) phi'.
            double s = 0.0, c = 0.0;
            for (int j = 1; j <= k; ++j) {
                const double jp = j * phi_[static_cast<size_t>(j)];
                s += jp * cos_[static_cast<size_t>(k - j)];
                c -= jp * sin_[static_cast<size_t>(k - j)];
            }
            sin_[kk] = s / k;
            cos_[kk] = c / k;
        }
        w2[kk] = product(omega_, omega_, k);
        q[kk] = cos_[kk] - f * sin_[kk];
        d[kk] = (k == 0 ? b.inv_mass_per_kg : 0.0) + r * r * b.inv_inertia * product(cos_, q, k);
        u[kk] = r * product(sin_, w2, k) + (k == 0 ? b.gravity_normal_m_s2 : 0.0);
        // n d = u, coefficient by coefficient.
        double nd = 0.0;
        for (int i = 0; i < k; ++i) nd += n[static_cast<size_t>(i)] * d[static_cast<size_t>(k - i)];
        n[kk] = (u[kk] - nd) / d[0];
        alpha[kk] = r * b.inv_inertia * product(n, q, k);
        ax[kk] = (k == 0 ? b.gravity_along_m_s2 : 0.0) + f * b.inv_mass_per_kg * n[kk];
    }
}

SlideSeries::Point SlideSeries::at(double tau) const {
    Point p;
    p.phi = phi_[K];
    p.omega = omega_[K];
    p.sin_phi = sin_[K];
    p.cos_phi = cos_[K];
    p.x_m = x_[K];
    p.vx_m_s = vx_[K];
    for (int k = K - 1; k >= 0; --k) {
        const auto kk = static_cast<size_t>(k);
        p.phi = p.phi * tau + phi_[kk];
        p.omega = p.omega * tau + omega_[kk];
        p.sin_phi = p.sin_phi * tau + sin_[kk];
        p.cos_phi = p.cos_phi * tau + cos_[kk];
        p.x_m = p.x_m * tau + x_[kk];
        p.vx_m_s = p.vx_m_s * tau + vx_[kk];
    }
    return p;
}

double SlideSeries::accurate_step_s() const {
    // From the angle's last two coefficients, as the pendulum's (pivot_motion.h).
    return accurate_series_step_s(phi_[K - 1], phi_[K], K);
}

}  // namespace polyroll::models
