// The segment model's faces timed from the energy integral (face_clock.h): the arc time against an
// independent brute-force quadrature, and whole runs against the stepped Taylor series (the reference
// integrator, kept as the fallback) over a matrix of polygons, ramps and fills.
#include <catch2/catch.hpp>

#include "test_helpers.h"

#include <algorithm>
#include <cmath>

#include "sim/models/face_clock.h"
#include "sim/models/reduced_models.h"
#include "sim/models/rolling_polygon.h"
#include "sim/scene_json.h"

using namespace polyroll;

namespace {

// integral dpsi / sqrt(2 (c - a cos psi)) by the composite Simpson rule on 200,000 panels: slow,
// simple and independent of the substitution and of Gauss-Legendre.
double simpson_time_s(double a, double c, double p1, double p2) {
    const int n = 200000;
    const double h = (p2 - p1) / n;
    auto f = [&](double p) { return 1.0 / std::sqrt(2.0 * (c - a * std::cos(p))); };
    double sum = f(p1) + f(p2);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(p1 + i * h);
    return std::fabs(h) * sum / 3.0;
}

}  // namespace

TEST_CASE("an arc's time from the energy integral matches brute-force quadrature", "[models][segments]") {
    const double a = 190.0;  // M g d / I of the default hexagon, about
    struct Case {
        double rate0, psi_from, psi_to;
    };
    // Over the top fast and nearly grazing it (A > 0), falling away from the top below its energy
    // (A < 0), once from just past a turning point, and
    // turning backwards.
    for (const Case& k : {Case{10.0, -0.6, 0.45}, Case{7.0, -0.5, 0.5}, Case{0.05, 0.02, 0.5}, Case{1.0, 0.1, 0.6},
                          Case{-6.0, 0.4, -0.3}}) {
        const double c = 0.5 * k.rate0 * k.rate0 + a * std::cos(k.psi_from);
        models::EnergyArc arc(a, c);
        INFO("rate0 = " << k.rate0 << ", from " << k.psi_from << " to " << k.psi_to);
        REQUIRE(arc.set_arc(k.psi_from, k.psi_to));
        const double t = arc.time_s(arc.u_from(), arc.u_to());
        CHECK(t == Approx(simpson_time_s(a, c, k.psi_from, k.psi_to)).epsilon(1e-9));
        // The point reached at half that time lies where the brute force takes half the time.
        const models::ArcPoint half = arc.point(arc.u_after(arc.u_from(), 0.5 * t));
        CHECK(simpson_time_s(a, c, k.psi_from, half.psi_rad) == Approx(0.5 * t).epsilon(1e-9));
        CHECK(half.rate_rad_s * half.rate_rad_s == Approx(2.0 * (c - a * std::cos(half.psi_rad))).epsilon(1e-9));
    }
    // A turning point before the target: the arc is refused (the caller steps it).
    const double c_low = a * std::cos(0.3);  // at rest at psi = -0.3, below the top's energy
    models::EnergyArc swing(a, c_low + 0.5);
    CHECK_FALSE(swing.set_arc(-0.4, 0.2));
}

TEST_CASE("both reduced models timed from the energy integral agree with the stepped series", "[models][segments]") {
    int cases = 0, timed = 0;
    for (const models::FillMotion motion : {models::FillMotion::relevel, models::FillMotion::frozen}) {
    for (int n : {4, 6, 8, 18}) {
        for (double angle : {5.0, 10.0, 20.0, 30.0}) {
            for (double r : {0.0, 0.25, 0.5}) {
                const Scene s = test::scene_with(
                    {{"shell", {{"sides", n}}}, {"fill", {{"ratio", r}}}, {"ramp", {{"angle_deg", angle}}}});
                const models::RollingBody body = models::rolling_body(s);
                const models::RampFrame track = models::ramp_frame(s);
                const models::RollingRun ref = models::roll(body, motion, track, models::FaceTiming::stepped);
                const models::RollingRun fast = models::roll(body, motion, track, models::FaceTiming::energy_integral);
                const Measurements& a = ref.measured;
                const Measurements& b = fast.measured;
                INFO((motion == models::FillMotion::frozen ? "rigid" : "segments")
                     << ": n = " << n << ", theta = " << angle << " deg, r = " << r << ": " << to_string(a.behaviour));
                ++cases;
                timed += fast.timed_arcs > 0;
                CHECK(ref.timed_arcs == 0);
                REQUIRE(to_string(a.behaviour) == to_string(b.behaviour));
                REQUIRE(a.impacts.size() == b.impacts.size());
                REQUIRE(a.trajectory.size() == b.trajectory.size());
                CHECK(ref.model_valid == fast.model_valid);
                CHECK(b.distance_m == Approx(a.distance_m).epsilon(1e-9).margin(1e-12));
                CHECK(b.end_time_s == Approx(a.end_time_s).epsilon(1e-9));
                CHECK(a.stop_time_s.has_value() == b.stop_time_s.has_value());
                if (a.stop_time_s && b.stop_time_s) CHECK(*b.stop_time_s == Approx(*a.stop_time_s).epsilon(1e-9));
                CHECK(a.terminal_velocity_m_s.has_value() == b.terminal_velocity_m_s.has_value());
                if (a.terminal_velocity_m_s && b.terminal_velocity_m_s)
                    CHECK(*b.terminal_velocity_m_s == Approx(*a.terminal_velocity_m_s).epsilon(1e-9));
                if (ref.model_invalid_time_s && fast.model_invalid_time_s)
                    CHECK(*fast.model_invalid_time_s == Approx(*ref.model_invalid_time_s).epsilon(1e-9));
                double worst_m = 0.0;
                for (size_t i = 0; i < a.trajectory.size(); ++i) {
                    // The rows fall at the same sample times; the last is the run's end.
                    CHECK(b.trajectory[i].time_s == Approx(a.trajectory[i].time_s).epsilon(1e-9));
                    worst_m = std::max(worst_m, std::fabs(b.trajectory[i].position_m - a.trajectory[i].position_m));
                }
                CHECK(worst_m <= 1e-9);
                for (size_t i = 0; i < a.impacts.size(); ++i)
                    CHECK(b.impacts[i].time_s == Approx(a.impacts[i].time_s).epsilon(1e-9));
                CHECK(fast.hop_pivots == ref.hop_pivots);
                // All of a run is stepped only where it stops at its first impact (rocking from rest).
                if (fast.timed_arcs == 0) CHECK(a.impacts.size() <= 1);
            }
        }
    }
    }
    // The matrix exercises the new path, not only the fallback (3 of the 96 cases, n = 4 half full,
    // stop at their first impact rocking from rest: all of those is stepped).
    CHECK(cases == 96);
    CHECK(timed >= cases - 3);
}

TEST_CASE("the segment model times most faces in one go", "[models][segments]") {
    const Scene s = resolve_scene({});
    const models::RollingRun run = models::roll(models::rolling_body(s), models::FillMotion::relevel, models::ramp_frame(s),
                                                models::FaceTiming::energy_integral);
    REQUIRE(run.measured.behaviour == Behaviour::rolled_to_end);
    // One arc per face, and the stepper only at the release (which starts at rest).
    CHECK(run.timed_arcs >= static_cast<long>(run.measured.impacts.size()));
    CHECK(run.steps <= run.timed_arcs + 5);
}
