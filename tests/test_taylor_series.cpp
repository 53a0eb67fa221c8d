// The rigid polygon's integrator and root finder (sim/reduced/taylor_series.h, sim/reduced/root_finder.h): a
// face's time along the pendulum's series against an independent brute-force quadrature of the
// energy integral, and the root finder on a smooth crossing and on a jump.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "sim/reduced/pivot_motion.h"
#include "sim/reduced/root_finder.h"

using namespace polyroll;

namespace {

// integral dpsi / sqrt(2 (c - a cos psi)) by the composite Simpson rule on 200,000 panels: slow,
// simple and independent of the series.
double simpson_time_s(double a, double c, double p1, double p2) {
    const int n = 200000;
    const double h = (p2 - p1) / n;
    auto f = [&](double p) { return 1.0 / std::sqrt(2.0 * (c - a * std::cos(p))); };
    double sum = f(p1) + f(p2);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(p1 + i * h);
    return std::fabs(h) * sum / 3.0;
}

// The pendulum psi'' = a sin(psi) followed along its series, as the rolling polygon follows it, from
// psi_from at rate0 until psi reaches psi_to (the time, located by first_root) or the rate changes
// sign first (NaN). `at_s` > 0 instead stops there and gives psi in `psi_at`.
double series_time_s(double a, double psi_from, double rate0, double psi_to, double at_s = 0.0,
                     double* psi_at = nullptr) {
    const double dir = rate0 > 0.0 ? 1.0 : -1.0;
    double t = 0.0, psi = psi_from, rate = rate0;
    for (int step = 0; step < 100000; ++step) {
        const models::PendulumSeries s(psi, rate, a);
        double h = std::min(s.accurate_step_s(), 0.1);
        if (at_s > 0.0 && t + h >= at_s) {
            *psi_at = s.psi(at_s - t);
            return at_s;
        }
        const double psi_h = s.psi(h), rate_h = s.rate(h);
        if (dir * (psi_h - psi_to) >= 0.0) {
            auto f = [&](double tau) { return dir * (psi_to - s.psi(tau)); };
            return t + models::first_root(f, 0.0, f(0.0), h, f(h), 0.0);
        }
        if (rate_h * dir <= 0.0) return std::numeric_limits<double>::quiet_NaN();
        t += h;
        psi = psi_h;
        rate = rate_h;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

TEST_CASE("a face's time along the pendulum series matches brute-force quadrature", "[models][series]") {
    const double a = 190.0;  // M g d / I of the default hexagon, about
    struct Case {
        double rate0, psi_from, psi_to;
    };
    // Over the top fast and nearly grazing it, falling away from the top below its energy, once from
    // just past a turning point, and turning backwards.
    for (const Case& k : {Case{10.0, -0.6, 0.45}, Case{7.0, -0.5, 0.5}, Case{0.05, 0.02, 0.5}, Case{1.0, 0.1, 0.6},
                          Case{-6.0, 0.4, -0.3}}) {
        const double c = 0.5 * k.rate0 * k.rate0 + a * std::cos(k.psi_from);
        INFO("rate0 = " << k.rate0 << " from " << k.psi_from << " to " << k.psi_to);
        const double t = series_time_s(a, k.psi_from, k.rate0, k.psi_to);
        REQUIRE(std::isfinite(t));
        CHECK(t == Approx(simpson_time_s(a, c, k.psi_from, k.psi_to)).epsilon(1e-9));
        // The point reached at half that time lies where the brute force takes half the time.
        double psi_half = 0.0;
        series_time_s(a, k.psi_from, k.rate0, k.psi_to, 0.5 * t, &psi_half);
        CHECK(simpson_time_s(a, c, k.psi_from, psi_half) == Approx(0.5 * t).epsilon(1e-9));
    }
    // Below the top's energy, short of it: the body swings back before reaching psi = 0.2.
    CHECK(std::isnan(series_time_s(a, -0.4, std::sqrt(1.0), 0.2)));
}

TEST_CASE("the root finder locates the first crossing to rounding or to its tolerance", "[models][series]") {
    const double root = 0.7390851332151607;  // cos(x) = x
    auto f = [](double x) { return std::cos(x) - x; };
    long evaluations = 0;
    const double x = models::first_root(f, 0.0, f(0.0), 1.0, f(1.0), 0.0, evaluations);
    CHECK(x == Approx(root).margin(1e-15));
    CHECK(f(x) <= 0.0);  // the event has happened at the point returned
    CHECK(evaluations <= 15);
    const double coarse = models::first_root(f, 0.0, f(0.0), 1.0, f(1.0), 1e-6);
    CHECK(coarse >= root);
    CHECK(coarse - root <= 1e-6);
    // A jump, as where a contact's force changes form: still found, from above.
    auto step = [](double t) { return t < 0.3 ? 1.0 : -2.0; };
    const double at = models::first_root(step, 0.0, 1.0, 1.0, -2.0, 0.0);
    CHECK(at >= 0.3);
    CHECK(at == Approx(0.3).margin(1e-15));
    // Already there at the bracket's start.
    CHECK(models::first_root(f, root + 0.1, f(root + 0.1), 1.0, f(1.0), 0.0) == root + 0.1);
    // With the derivative (a series' value and rate): Newton steps, fewer evaluations, the same point
    // to rounding and still where the event has happened.
    auto sloped = [](double x) { return models::Slope{std::cos(x) - x, -std::sin(x) - 1.0}; };
    long newton_evaluations = 0;
    const double xn = models::first_root(sloped, 0.0, f(0.0), 1.0, f(1.0), 0.0, newton_evaluations);
    CHECK(xn == Approx(root).margin(1e-15));
    CHECK(f(xn) <= 0.0);
    CHECK(newton_evaluations < evaluations);
    const double coarse_newton = models::first_root(sloped, 0.0, f(0.0), 1.0, f(1.0), 1e-6);
    CHECK(coarse_newton >= root);
    CHECK(coarse_newton - root <= 1e-6);
}

TEST_CASE("a series built for a short step stops at a lower order and agrees with the full one", "[models][series]") {
    const double a = 190.0, psi0 = -0.3, rate0 = 5.0;
    const models::PendulumSeries full(psi0, rate0, a);
    REQUIRE(full.order() == models::kSeriesOrder);
    for (double want : {0.002, 0.01, 0.03}) {
        INFO("step wanted " << want << " s");
        const models::PendulumSeries s(psi0, rate0, a, want);
        CHECK(s.order() < models::kSeriesOrder);
        CHECK(s.accurate_step_s() == want);
        for (double tau : {0.25 * want, want}) {
            CHECK(std::fabs(s.psi(tau) - full.psi(tau)) <= 1e-14);
            CHECK(std::fabs(s.rate(tau) - full.rate(tau)) <= 1e-12);
        }
    }
    // Wanting more than the whole order is accurate over: the whole order's step, for the caller to cap.
    const models::PendulumSeries far(psi0, rate0, a, 10.0);
    CHECK(far.order() == models::kSeriesOrder);
    CHECK(far.accurate_step_s() == full.accurate_step_s());
}
