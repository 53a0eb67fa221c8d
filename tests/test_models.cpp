// The reduced models (docs/physics.md): triangle formulas, the level fill region, the rigid impact
// model's closed forms, energy books, and the cross-check against the grain simulation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "sim/geometry/geometry.h"
#include "sim/reduced/composite_body.h"
#include "sim/reduced/reduced_models.h"
#include "sim/reduced/rolling_polygon.h"
#include "sim/files/results_io.h"
#include "sim/scene/scene_json.h"
#include "sim/geometry/shell_properties.h"
#include "sim/model_choice.h"
#include "sim/model_registry.h"
#include "sim/scene/scene_fields.h"
#include "sim/grains/world_builder.h"
#include "test_helpers.h"

using namespace polyroll;
using geom::Vec2;

namespace {

using geom::kPi;

using test::scene_with;

// A uniform solid regular polygon laid out like the shell (face (0, 1) down, vertex 1 downhill).
models::RollingBody solid_polygon(int n, double circumradius_m, double mass_kg) {
    models::RollingBody b;
    b.outer_m = geom::regular_polygon(n, circumradius_m, -kPi / 2.0 - kPi / n);
    b.shell.mass_kg = mass_kg;
    const double c = std::cos(kPi / n);
    b.shell.inertia_cm_kg_m2 = mass_kg * circumradius_m * circumradius_m * (1.0 + 2.0 * c * c) / 6.0;
    return b;
}

// The track of a scene, for a body of outer circumradius R released like the scene's shell.
models::RampFrame track_for(int n, double circumradius_m, double angle_deg, double length_m = 2.539) {
    const double theta = angle_deg * kPi / 180.0;
    models::RampFrame t;
    t.angle_deg = angle_deg;
    t.gravity_m_s2 = 9.81;
    t.start_rotation_rad = std::max(0.0, kPi / n - theta) + 1.0 * kPi / 180.0;  // vertex release, 1 deg tilt
    t.end_centre_x_m = length_m - circumradius_m;
    t.time_limit_s = 60.0;
    t.sample_hz = 30.0;
    t.rest_speed_m_s = 0.002;
    t.rest_time_s = 0.5;
    return t;
}

// The brief's polar moment, written independently: mass (a^2 + b^2 + c^2) / 36 per unit density.
double side_form_moment(Vec2 a, Vec2 b, Vec2 c, double area) {
    auto sq = [](Vec2 v) { return geom::dot(v, v); };
    return area * (sq(b - a) + sq(c - b) + sq(a - c)) / 36.0;
}

// Integral of |p - centre|^2 over a triangle by the edge-midpoint rule, exact for quadratics.
double midpoint_rule_moment(Vec2 a, Vec2 b, Vec2 c, Vec2 centre) {
    const double area = std::fabs(geom::cross(b - a, c - a)) / 2.0;
    auto f = [&](Vec2 p) { return geom::dot(p - centre, p - centre); };
    return area / 3.0 * (f(0.5 * (a + b)) + f(0.5 * (b + c)) + f(0.5 * (c + a)));
}

// Splits a triangle 4^depth times and sums centroid-rule moments: converges to the integral as h^2.
void split_sum(Vec2 a, Vec2 b, Vec2 c, int depth, Vec2 centre, double& area, double& moment, Vec2& first_moment) {
    if (depth == 0) {
        const double ar = std::fabs(geom::cross(b - a, c - a)) / 2.0;
        const Vec2 g = (1.0 / 3.0) * (a + b + c);
        area += ar;
        first_moment = first_moment + ar * g;
        moment += ar * geom::dot(g - centre, g - centre);
        return;
    }
    const Vec2 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
    split_sum(a, ab, ca, depth - 1, centre, area, moment, first_moment);
    split_sum(ab, b, bc, depth - 1, centre, area, moment, first_moment);
    split_sum(ca, bc, c, depth - 1, centre, area, moment, first_moment);
    split_sum(ab, bc, ca, depth - 1, centre, area, moment, first_moment);
}

double total_energy_scale(const RunResult& r) {
    // Initial total energy measured from the lowest point the centre could reach: the whole ramp's
    // drop plus the pivot radius.
    const double m = r.shell.mass_kg + r.fill_mass_kg;
    const double theta = r.scene.ramp.angle_deg * kPi / 180.0;
    return m * r.scene.run.gravity_m_s2 * (r.shell.pivot_radius_m + r.scene.ramp.length_m * std::sin(theta));
}

}  // namespace

TEST_CASE("triangle properties match independent computations", "[models]") {
    const std::vector<std::array<Vec2, 3>> triangles = {
        {Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}},
        {Vec2{0.3, -0.2}, Vec2{2.5, 0.4}, Vec2{-0.7, 1.9}},
        {Vec2{0.01, 0.02}, Vec2{0.013, 0.021}, Vec2{0.0105, 0.035}},  // a thin one, centimetres
        {Vec2{-1, -1}, Vec2{-3, 2}, Vec2{4, -0.5}},                   // clockwise
        {Vec2{0, 0}, Vec2{10, 0}, Vec2{20, 0.001}},                   // nearly degenerate
    };
    for (const auto& t : triangles) {
        const geom::AreaProperties p = geom::triangle_properties(t[0], t[1], t[2]);
        // Area and centroid by shoelace over the polygon, a different code path.
        const geom::AreaProperties q = geom::polygon_properties({t[0], t[1], t[2]});
        CHECK(p.area == Approx(q.area).epsilon(1e-12));
        CHECK(p.centroid.x == Approx(q.centroid.x).epsilon(1e-12).margin(1e-15));
        CHECK(p.centroid.y == Approx(q.centroid.y).epsilon(1e-12).margin(1e-15));
        // Polar moment: the side-length form, an exact quadrature, and a brute-force sum.
        CHECK(p.polar_moment_cm == Approx(side_form_moment(t[0], t[1], t[2], p.area)).epsilon(1e-10));
        CHECK(p.polar_moment_cm == Approx(midpoint_rule_moment(t[0], t[1], t[2], p.centroid)).epsilon(1e-10));
        double area = 0.0, moment = 0.0;
        Vec2 first;
        split_sum(t[0], t[1], t[2], 6, p.centroid, area, moment, first);
        CHECK(area == Approx(p.area).epsilon(1e-12));
        CHECK(first.x / area == Approx(p.centroid.x).epsilon(1e-10).margin(1e-13));
        CHECK(first.y / area == Approx(p.centroid.y).epsilon(1e-10).margin(1e-13));
        // Centroid-rule error is (h^2 / 36)-ish per piece: 4^-6 of the whole within a factor.
        CHECK(moment == Approx(p.polar_moment_cm).epsilon(1e-3));
    }
}

TEST_CASE("the fill's segments combine to the region's mass properties", "[models]") {
    // The triangles summed with the parallel-axis theorem against the shoelace moments of the region.
    for (int n : {3, 4, 6, 7, 18, 64}) {
        const auto inner = geom::regular_polygon(n, 0.05, -kPi / 2.0 - kPi / n);
        for (double turn_deg : {0.0, 13.0, 100.0}) {
            const Vec2 up = geom::rotate(Vec2{0.0, 1.0}, turn_deg * kPi / 180.0);
            for (double r : {0.05, 0.375, 0.74, 1.0}) {
                const double density = 65.7;
                const models::FillSegments f = models::fill_segments(inner, up, r, density);
                const geom::AreaProperties region = geom::polygon_properties(f.region);
                INFO("n = " << n << ", turn " << turn_deg << " deg, r = " << r);
                CHECK(f.mass.mass_kg == Approx(density * region.area).epsilon(1e-12));
                CHECK(f.mass.centre_of_mass_m.x == Approx(region.centroid.x).epsilon(1e-9).margin(1e-14));
                CHECK(f.mass.centre_of_mass_m.y == Approx(region.centroid.y).epsilon(1e-9).margin(1e-14));
                CHECK(f.mass.inertia_cm_kg_m2 == Approx(density * region.polar_moment_cm).epsilon(1e-9));
            }
        }
    }
    // combine() against a body computed whole: two halves of a rectangle.
    models::MassProperties left{2.0, Vec2{-0.5, 0.0}, 2.0 * (1.0 + 1.0) / 12.0};  // 1 x 1 squares of mass 2
    models::MassProperties right{2.0, Vec2{0.5, 0.0}, 2.0 * (1.0 + 1.0) / 12.0};
    const models::MassProperties whole = models::combine(left, right);
    CHECK(whole.mass_kg == 4.0);
    CHECK(whole.centre_of_mass_m.x == Approx(0.0).margin(1e-15));
    CHECK(whole.inertia_cm_kg_m2 == Approx(4.0 * (4.0 + 1.0) / 12.0).epsilon(1e-14));  // 2 x 1 plate
}

TEST_CASE("the clipped fill region holds area fraction r within 1e-9", "[models]") {
    for (int n = 3; n <= 64; ++n) {
        const auto inner = geom::regular_polygon(n, 0.0336, -kPi / 2.0 - kPi / n);
        const double total = geom::polygon_properties(inner).area;
        // Gravity from several directions in the polygon's frame: a face down, a vertex down, between.
        for (double turn : {0.0, kPi / n, 0.37 * 2.0 * kPi / n, 1.234}) {
            const Vec2 up = geom::rotate(Vec2{0.0, 1.0}, turn);
            for (int i = 0; i <= 32; ++i) {
                for (double r : {i / 32.0, std::min(1.0, i / 32.0 + 1e-7)}) {
                    const double level = models::fill_level(inner, up, r);
                    const double area = geom::polygon_properties(geom::clip_half_plane(inner, up, level)).area;
                    INFO("n = " << n << ", turn = " << turn << ", r = " << r);
                    REQUIRE(std::fabs(area / total - r) <= 1e-9);
                }
            }
        }
    }
}

TEST_CASE("solid polygons lose the brief's share of energy at each impact", "[models]") {
    // docs/physics.md: Q_4 = 0.0625 and Q_6 = 0.4187 for uniform solid polygons.
    struct Case {
        int n;
        double angle_deg;
        double q;
        double tolerance;
    };
    for (const Case c : {Case{4, 30.0, 0.0625, 1e-12}, Case{6, 10.0, 0.4187, 5e-5}}) {
        const models::RollingRun run =
            models::roll(solid_polygon(c.n, 0.035, 0.2), models::FillMotion::frozen, track_for(c.n, 0.035, c.angle_deg));
        REQUIRE(!run.measured.impacts.empty());
        for (const FaceImpact& f : run.measured.impacts) CHECK(f.ratio() == Approx(c.q).margin(c.tolerance));
    }
}

TEST_CASE("a solid triangle does not roll past its first impact", "[models]") {
    for (double angle : {2.0, 10.0, 20.0, 35.0, 55.0}) {
        const models::RollingRun run =
            models::roll(solid_polygon(3, 0.035, 0.2), models::FillMotion::frozen, track_for(3, 0.035, angle));
        INFO("theta = " << angle << " deg");
        CHECK(run.measured.behaviour == Behaviour::stopped_at_first_impact);
        REQUIRE(run.measured.impacts.size() == 1);
        CHECK(run.measured.impacts[0].kinetic_after_J == 0.0);
        // It lands on face (1, 2) and stays there, its centre above that face's middle, x = 1.5 sides;
        // it started above vertex 1 (x = 1 side) turned by the release rotation about it.
        const double side = geom::regular_polygon_side(3, 0.035);
        const models::RampFrame t = track_for(3, 0.035, angle);
        const double start_x = side + 0.035 * std::sin(t.start_rotation_rad - kPi / 3.0);
        CHECK(run.measured.distance_m == Approx(1.5 * side - start_x).epsilon(1e-9));
    }
}

TEST_CASE("a shell rocking on a face lands only moving onto it and stops once its rocking dies down", "[models]") {
    // The octagon 0.375 full of BB at 14 deg comes to rest on its first face rocking from one end vertex
    // to the other. A step that starts on the face (just landed) and rocks out and back within one
    // check interval once found the face at the step's start, moving away from it: a chain of impacts
    // in no time that stopped the shell mid-swing, at 0.04 m/s, at 0.698 s.
    const Scene s = scene_with({{"shell", "octagon-small"},
                                {"fill", {{"ratio", 0.375}}},
                                {"ramp", {{"angle_deg", 14.0}}},
                                {"run", {{"model", "rigid"}, {"sample_hz", 1000.0}}}});
    const RunResult r = run_scene(s);
    REQUIRE(r.measured.stop_time_s);
    const double stop = *r.measured.stop_time_s;
    CHECK(stop > 0.74);
    // The rows of the last millisecond before the stop: slower than the rest speed, give or take what
    // the rocking gains in a millisecond.
    const auto last = std::find_if(r.measured.trajectory.rbegin(), r.measured.trajectory.rend(),
                                   [&](const TrajectorySample& row) { return row.time_s < stop; });
    REQUIRE(last != r.measured.trajectory.rend());
    CHECK(stop - last->time_s <= 1e-3);
    CHECK(std::fabs(last->speed_m_s) < 5.0 * s.run.rest_speed_m_s);
}

TEST_CASE("the rigid model's steady state is the closed form (1 - Q) KE_before = M g s sin(theta)", "[models]") {
    SECTION("solid hexagon") {
        const double m = 0.2, radius = 0.035, angle = 10.0;
        const models::RollingRun run =
            models::roll(solid_polygon(6, radius, m), models::FillMotion::frozen, track_for(6, radius, angle, 5.0));
        REQUIRE(run.measured.behaviour == Behaviour::rolled_to_end);
        const double q = rigid_impact_energy_ratio(6, m, solid_polygon(6, radius, m).shell.inertia_cm_kg_m2, radius);
        const double h = geom::regular_polygon_side(6, radius) * std::sin(angle * kPi / 180.0);
        CHECK((1.0 - q) * run.measured.impacts.back().kinetic_before_J == Approx(m * 9.81 * h).epsilon(1e-9));
    }
    SECTION("the empty hollow shell of a scene, through run_scene") {
        const Scene s = scene_with({{"fill", {{"ratio", 0.0}}}, {"run", {{"model", "rigid"}}}, {"ramp", {{"angle_deg", 12.0}}}});
        const RunResult r = run_scene(s);
        REQUIRE(r.measured.behaviour == Behaviour::rolled_to_end);
        REQUIRE(r.measured.impacts.size() > 30);
        const double q = rigid_impact_energy_ratio(6, r.shell.mass_kg, r.shell.inertia_kg_m2, r.shell.pivot_radius_m);
        const double h = r.shell.outer_side_m * std::sin(12.0 * kPi / 180.0);
        CHECK((1.0 - q) * r.measured.impacts.back().kinetic_before_J ==
              Approx(r.shell.mass_kg * 9.81 * h).epsilon(1e-9));
        // The terminal velocity is a face per face interval at that energy.
        REQUIRE(r.measured.terminal_velocity_m_s);
        CHECK(r.model_valid);
    }
}

TEST_CASE("the friction the rigid model's rolling needs, against closed forms", "[models]") {
    const int n = 6;
    const double m = 0.2, radius = 0.035, angle = 10.0, theta = angle * kPi / 180.0;
    const models::RollingBody body = solid_polygon(n, radius, m);
    const models::RollingRun run = models::roll(body, models::FillMotion::frozen, track_for(n, radius, angle, 1.0));
    REQUIRE(run.measured.impacts.size() > 5);
    // At an impact face (A, B) lands, A = (0, 0) and B = (s, 0), the centre of mass at (s / 2, h):
    // v_cm = omega (h, -s / 2) before and omega' (h, s / 2) after, so the impulse at B is
    // M ((omega' - omega) h, (omega' + omega) s / 2), with omega' / omega = sqrt(Q) (symmetric body).
    const double side = geom::regular_polygon_side(n, radius), h = radius * std::cos(kPi / n);
    const double ratio = std::sqrt(rigid_impact_energy_ratio(n, m, body.shell.inertia_cm_kg_m2, radius));
    CHECK(run.max_impact_friction_share == Approx((1.0 - ratio) * h / ((1.0 + ratio) * 0.5 * side)).epsilon(1e-9));
    // Released from rest, the friction holds the body against the slope: tan(theta) of the normal
    // force at the start, and more once it turns (the centripetal term unloads the pivot).
    CHECK(run.max_friction_share >= std::tan(theta) * (1.0 - 1e-6));
    CHECK(run.max_friction_share < 1.0);
}

TEST_CASE("energy books close in both reduced models", "[models]") {
    for (const char* model : {"rigid", "segments"}) {
        for (int n : {3, 4, 6, 8, 18, 64}) {
            for (double r : {0.0, 0.125, 0.375, 0.74, 1.0}) {
                for (double angle : {4.0, 15.0, 30.0}) {
                    const Scene s = scene_with({{"shell", {{"sides", n}}},
                                                {"fill", {{"ratio", r}}},
                                                {"ramp", {{"angle_deg", angle}}},
                                                {"run", {{"model", model}, {"sample_hz", 500.0}}}});
                    const RunResult res = run_scene(s);
                    INFO(model << ", n = " << n << ", r = " << r << ", theta = " << angle << " deg: "
                               << to_string(res.measured.behaviour));
                    REQUIRE(res.measured.behaviour != Behaviour::diverged);
                    REQUIRE(res.measured.trajectory.size() >= 2);
                    const double scale = total_energy_scale(res);
                    double worst = 0.0, last_dissipated = 0.0;
                    bool dissipation_grows = true;
                    for (const TrajectorySample& t : res.measured.trajectory) {
                        worst = std::max(worst, std::fabs(t.kinetic_J + t.potential_J + t.dissipated_J));
                        if (t.dissipated_J < last_dissipated - 1e-15 * scale) dissipation_grows = false;
                        last_dissipated = t.dissipated_J;
                    }
                    CHECK(worst <= 1e-9 * scale);
                    CHECK(dissipation_grows);
                    // Every impact loses energy; none creates it.
                    for (const FaceImpact& f : res.measured.impacts) CHECK(f.kinetic_after_J <= f.kinetic_before_J);
                }
            }
        }
    }
}

TEST_CASE("the segment model is the rigid model when the fill cannot move", "[models]") {
    // Empty (nothing to re-level) and full (the level region is the whole inside): identical runs.
    for (double r : {0.0, 1.0}) {
        for (double angle : {8.0, 20.0}) {
            Scene s = scene_with({{"fill", {{"ratio", r}}}, {"ramp", {{"angle_deg", angle}}}, {"run", {{"model", "rigid"}}}});
            const RunResult rigid = run_scene(s);
            s.run.model = Model::segments;
            const RunResult seg = run_scene(s);
            INFO("r = " << r << ", theta = " << angle);
            REQUIRE(rigid.measured.trajectory.size() == seg.measured.trajectory.size());
            CHECK(rigid.measured.impacts.size() == seg.measured.impacts.size());
            // Equal up to rounding: the segment model recomputes the (unchanged) fill after each impact.
            CHECK(rigid.measured.distance_m == Approx(seg.measured.distance_m).epsilon(1e-12));
            CHECK(rigid.measured.end_time_s == Approx(seg.measured.end_time_s).epsilon(1e-12));
            CHECK(to_string(rigid.measured.behaviour) == to_string(seg.measured.behaviour));
        }
    }
}

TEST_CASE("a partly filled polygon re-levels and books the fill's drop", "[models]") {
    // Fill 3/8: after an impact the level surface is tilted in the polygon's frame, so re-levelling
    // drops the fill's centre of mass and books that energy as dissipated.
    const Scene s = scene_with({{"fill", {{"ratio", 0.375}}}, {"ramp", {{"angle_deg", 20.0}}}, {"run", {{"model", "segments"}}}});
    const models::RollingRun run = models::roll(models::rolling_body(s), models::FillMotion::relevel, models::ramp_frame(s));
    REQUIRE(!run.measured.impacts.empty());
    CHECK(run.relevel_dissipated_J > 0.0);
    CHECK(run.fill_mass_kg == Approx(0.375 * shell_properties(s.shell).inside_volume_m3 * s.fill.material.bulk_density_kg_m3).epsilon(1e-12));
}

TEST_CASE("the reduced models start where the grain simulation's shell starts", "[models]") {
    for (int n : {3, 6, 18}) {
        for (const char* pose : {"vertex", "face"}) {
            const Scene s = scene_with({{"shell", {{"sides", n}}}, {"release", {{"pose", pose}, {"tilt_deg", 2.0}}},
                                        {"run", {{"model", "rigid"}}}});
            const ShellProperties sp = shell_properties(s.shell);
            const ShellPose p = release_pose(s, sp);
            // The rigid model measures from the release centre: reconstruct it from its own geometry.
            const models::RampFrame t = models::ramp_frame(s);
            CHECK(t.start_rotation_rad == Approx(-p.angle_rad));
            const Vec2 v1 = shell_outer_polygon_m(s.shell)[1];
            const Vec2 centre = Vec2{sp.outer_side_m, 0.0} + geom::rotate(-1.0 * v1, p.angle_rad);
            CHECK(centre.x == Approx(p.centre_m.x).epsilon(1e-12));
            CHECK(centre.y == Approx(p.centre_m.y).epsilon(1e-12));
            const RunResult r = run_scene(s);
            CHECK(r.measured.trajectory.front().position_m == 0.0);
            CHECK(r.measured.trajectory.front().time_s == 0.0);
        }
    }
}

TEST_CASE("the rigid model flags the angle where the polygon would hop", "[models]") {
    // Independent closed form for the symmetric body at steady state: just before an impact the arm
    // from pivot to centre leans pi/n downhill of the ramp normal, and
    // omega^2 = 2 KE* / I_pivot with (1 - Q) KE* = M g s sin(theta). The normal force there is
    // N = M (g cos(theta) - alpha r_x - omega^2 r_y); the model must be invalid just above the angle
    // where this turns negative and valid just below it.
    const int n = 6;
    const double m = 0.2, radius = 0.035, g = 9.81;
    const models::RollingBody body = solid_polygon(n, radius, m);
    const double i0 = body.shell.inertia_cm_kg_m2, ip = i0 + m * radius * radius;
    const double q = rigid_impact_energy_ratio(n, m, i0, radius);
    const double side = geom::regular_polygon_side(n, radius);
    auto normal_before_impact = [&](double theta) {
        const double rx = radius * std::sin(kPi / n), ry = radius * std::cos(kPi / n);
        const double alpha = m * g * (rx * std::cos(theta) + ry * std::sin(theta)) / ip;
        const double ke = m * g * side * std::sin(theta) / (1.0 - q);
        return m * (g * std::cos(theta) - alpha * rx - 2.0 * ke / ip * ry);
    };
    double lo = 0.01, hi = 1.5;
    for (int i = 0; i < 100; ++i) (normal_before_impact(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
    const double critical_deg = lo * 180.0 / kPi;
    const auto below = models::roll(body, models::FillMotion::frozen, track_for(n, radius, critical_deg - 0.5, 20.0));
    const auto above = models::roll(body, models::FillMotion::frozen, track_for(n, radius, critical_deg + 0.5, 20.0));
    CHECK(below.model_valid);
    CHECK(below.min_normal_force_N > 0.0);
    CHECK_FALSE(above.model_valid);
    REQUIRE(above.model_invalid_time_s);
    CHECK(*above.model_invalid_time_s > 0.0);
    CHECK(*above.model_invalid_time_s < above.measured.end_time_s);
    // Run on past lift-off, the faces that would hop: none below; above, each face from the first
    // hop on (the speed before an impact only grows towards the steady state, so once the normal
    // force turns negative it does so on every later face), the one it lifted off on included.
    CHECK(below.hop_pivots == 0);
    long faces_after = 0;
    for (const FaceImpact& f : above.measured.impacts) faces_after += f.time_s > *above.model_invalid_time_s;
    CHECK(above.hop_pivots >= faces_after);
    CHECK(above.hop_pivots <= faces_after + 1);
    CHECK(above.hop_pivots >= 2);
}

TEST_CASE("the reduced models' summary says which model ran and whether it held", "[models]") {
    const Scene s = scene_with({{"run", {{"model", "rigid"}}}, {"fill", {{"ratio", 0.0}}}, {"ramp", {{"angle_deg", 35.0}}}});
    const RunResult r = run_scene(s);
    const auto j = summary_json(r);
    CHECK(j["results"]["model"] == "rigid");
    CHECK(j["scene"]["run"]["model"] == "rigid");
    CHECK_FALSE(j.contains("engine"));
    CHECK(j["results"]["model_valid"] == false);  // an empty hexagon at 35 degrees hops
    CHECK(j["results"]["model_invalid_time_s"].is_number());
    Scene g = s;
    g.run.model = Model::grains;
    g.ramp.angle_deg = 20.0;
    g.run.time_limit_s = 0.05;
    const auto jg = summary_json(run_scene(g));
    CHECK(jg["results"]["model"] == "grains");
    CHECK(jg["results"]["model_valid"] == true);
    CHECK(jg["results"]["model_invalid_time_s"].is_null());
    CHECK(jg.contains("engine"));
}

TEST_CASE("the reduced models are deterministic", "[models]") {
    const Scene s = scene_with({{"run", {{"model", "segments"}}}, {"fill", {{"ratio", 0.3}}}});
    CHECK(trajectory_csv(run_scene(s)) == trajectory_csv(run_scene(s)));
}

TEST_CASE("an empty shell rolls alike in the rigid model and the grain simulation", "[models]") {
    // The grain simulation of an empty shell is one Box2D body: the rigid model is its exact limit.
    // At the precise fidelity they must agree on the impact energy ratio (mean of the first ten
    // impacts) within 3% and on the position at the rigid model's tenth impact within 5%.
    const Scene s = scene_with({{"fill", {{"ratio", 0.0}}}, {"fidelity", {{"preset", "precise"}}},
                                {"run", {{"sample_hz", 1000.0}}}});
    Scene rigid_scene = s;
    rigid_scene.run.model = Model::rigid;
    const RunResult rigid = run_scene(rigid_scene);
    const RunResult grains = run_scene(s);
    REQUIRE(rigid.model_valid);
    REQUIRE(rigid.measured.impacts.size() >= 10);
    REQUIRE(grains.measured.impacts.size() >= 10);
    auto mean_ratio = [](const Measurements& m) {
        double sum = 0.0;
        for (int i = 0; i < 10; ++i) sum += m.impacts[static_cast<size_t>(i)].ratio();
        return sum / 10.0;
    };
    const double q_rigid = mean_ratio(rigid.measured), q_grains = mean_ratio(grains.measured);
    INFO("mean ratio over ten impacts: rigid " << q_rigid << ", grains " << q_grains);
    CHECK(std::fabs(q_grains / q_rigid - 1.0) <= 0.03);

    const FaceImpact& tenth = rigid.measured.impacts[9];
    const auto& traj = grains.measured.trajectory;
    auto after = std::lower_bound(traj.begin(), traj.end(), tenth.time_s,
                                  [](const TrajectorySample& a, double t) { return a.time_s < t; });
    REQUIRE(after != traj.begin());
    REQUIRE(after != traj.end());
    const auto before = after - 1;
    const double w = (tenth.time_s - before->time_s) / (after->time_s - before->time_s);
    const double x_grains = before->position_m + w * (after->position_m - before->position_m);
    INFO("position at t = " << tenth.time_s << " s: rigid " << tenth.position_m << " m, grains " << x_grains << " m");
    CHECK(std::fabs(x_grains / tenth.position_m - 1.0) <= 0.05);
}

TEST_CASE("the registry describes every model and auto picks only the models it may", "[models][registry]") {
    const std::string help = field_help(scene_field("run.model"));
    for (Model m : all_models()) {
        INFO(to_string(m));
        CHECK_FALSE(model_traits(m).description.get().empty());
        CHECK_THAT(help, Catch::Contains(to_string(m) + " (" + model_traits(m).description.get()));
    }
    CHECK_THAT(help, Catch::Contains(auto_rule_description()));
    // The window's tooltip lists only what the window offers.
    for (Model m : all_models())
        CHECK((model_help(everyday_models()).find(model_traits(m).description) != std::string::npos) ==
              model_traits(m).everyday);
    for (double ratio : {0.0, 0.25, 1.0}) {
        for (double curvature : {0.0, 1.7}) {
            const Scene s = test::with_model(
                test::scene_with({{"fill", {{"ratio", ratio}}}, {"ramp", {{"curvature_deg_per_m", curvature}}}}),
                Model::automatic);
            INFO("fill " << ratio << ", curvature " << curvature);
            for (Model m : models_a_run_may_use(s)) CHECK(model_traits(m).auto_may_pick);
            // Only a run with a fill has grains to step, and every choice but the empty shell's may step them.
            CHECK(may_step_grains(s) == (ratio > 0.0));
        }
    }
}

TEST_CASE("the tipped release in the reduced models: the pile as poured on the face, the whole body balanced on the vertex", "[models][release]") {
    for (const char* model : {"rigid", "segments"}) {
        for (const char* shell : {"hexagon-small", "octagon-small"}) {
            for (double fill : {0.25, 0.5}) {
                for (double angle : {10.0, 16.0, 22.0}) {
                    const Scene s = scene_with({{"shell", shell},
                                                {"fill", {{"ratio", fill}}},
                                                {"ramp", {{"angle_deg", angle}}},
                                                {"run", {{"model", model}}},
                                                {"release", {{"pose", "tipped"}}}});
                    const RunResult r = run_scene(s);
                    INFO(model << ", " << shell << ", r = " << fill << ", " << angle << " deg");
                    REQUIRE(r.measured.trajectory.size() > 2);
                    // Balanced past the pivot, it starts to roll forward, never back onto its face.
                    CHECK(r.measured.trajectory[1].position_m > 0.0);
                    CHECK(r.measured.trajectory[1].speed_m_s > 0.0);
                    CHECK(r.measured.distance_m > 0.0);
                }
            }
        }
    }
    // An empty or a full shell has no pile to pour on a face: the tipped release is the vertex release.
    for (double fill : {0.0, 1.0}) {
        const Scene vertex = scene_with({{"fill", {{"ratio", fill}}}, {"run", {{"model", "rigid"}}}});
        const Scene tipped = scene_with(
            {{"fill", {{"ratio", fill}}}, {"run", {{"model", "rigid"}}}, {"release", {{"pose", "tipped"}}}});
        const RunResult a = run_scene(vertex), b = run_scene(tipped);
        INFO("r = " << fill);
        CHECK(b.measured.distance_m == a.measured.distance_m);
        REQUIRE(b.measured.trajectory.size() == a.measured.trajectory.size());
        CHECK(b.measured.trajectory.back().angle_deg == a.measured.trajectory.back().angle_deg);
    }
}

// What the window and the frames draw for a fill no grain stands for (RunSnapshot::fill_region_local_m):
// the whole inside of a full shell, the rigid model's fill frozen as at release, the segment model's
// levelled again at each impact; nothing where the grains are drawn one by one.
TEST_CASE("a fill held as one body is in the snapshot as one region, as the model holds it", "[models][snapshot]") {
    auto area = [](const std::vector<Vec2>& p) { return geom::polygon_properties(p).area; };
    auto run_for = [](const Scene& s, double seconds) {
        std::unique_ptr<ModelRun> run = start_run(s);
        const long steps = std::lround(seconds * s.fidelity.step_hz);
        for (long i = 0; i < steps && run->step();) ++i;
        return run;
    };

    SECTION("a full shell under auto: the whole inside, at release and rolling") {
        const Scene s = scene_with(nlohmann::ordered_json::parse(R"({"fill": {"ratio": 1.0}, "ramp": {"angle_deg": 12}})"));
        const auto run = run_for(s, 0.5);
        const RunSnapshot snap = run->snapshot();
        REQUIRE(snap.time_s > 0.4);
        CHECK(snap.grains.empty());
        CHECK(area(snap.fill_region_local_m) == Approx(area(snap.inner_local_m)).epsilon(1e-9));
    }
    SECTION("rigid: the share r of the inside, the same region in the shell's frame throughout") {
        const Scene s = test::with_model(scene_with(nlohmann::ordered_json::parse(R"({"fill": {"ratio": 0.25}, "ramp": {"angle_deg": 25}})")),
                                   Model::rigid);
        const auto run = start_run(s);
        const std::vector<Vec2> at_release = run->snapshot().fill_region_local_m;
        CHECK(area(at_release) == Approx(0.25 * area(run->snapshot().inner_local_m)).epsilon(1e-6));
        for (int i = 0; i < 400 && run->step(); ++i) {
        }
        const RunSnapshot later = run->snapshot();
        REQUIRE(later.impacts >= 1);
        REQUIRE(later.fill_region_local_m.size() == at_release.size());
        for (size_t i = 0; i < at_release.size(); ++i) {
            CHECK(later.fill_region_local_m[i].x == at_release[i].x);
            CHECK(later.fill_region_local_m[i].y == at_release[i].y);
        }
    }
    SECTION("segments: levelled again at each impact, the same share") {
        const Scene s = test::with_model(scene_with(nlohmann::ordered_json::parse(R"({"fill": {"ratio": 0.25}, "ramp": {"angle_deg": 25}})")),
                                   Model::segments);
        const auto run = start_run(s);
        const RunSnapshot first = run->snapshot();
        const std::vector<Vec2> at_release = first.fill_region_local_m;
        RunSnapshot later = first;
        for (int i = 0; i < 2000 && run->step(); ++i) {
            later = run->snapshot();
            if (later.impacts >= 1) break;
        }
        REQUIRE(later.impacts >= 1);
        CHECK(area(later.fill_region_local_m) == Approx(0.25 * area(later.inner_local_m)).epsilon(1e-6));
        // Levelled with the shell turned by about one side: the region in the shell's frame has moved.
        const Vec2 c0 = geom::polygon_properties(at_release).centroid;
        const Vec2 c1 = geom::polygon_properties(later.fill_region_local_m).centroid;
        CHECK(geom::length(c1 - c0) > 0.2 * geom::length(c0));
    }
    SECTION("grains: each grain drawn, no region") {
        const Scene s = test::with_model(scene_with(nlohmann::ordered_json::parse(R"({"fill": {"ratio": 0.25}})")), Model::grains);
        const RunSnapshot snap = start_run(s)->snapshot();
        CHECK_FALSE(snap.grains.empty());
        CHECK(snap.fill_region_local_m.empty());
    }
}
