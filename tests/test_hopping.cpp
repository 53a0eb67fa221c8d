// The free rigid body that carries an empty shell on after lift-off (sim/reduced/free_body.h):
// exact flight, the impact law (no bounce, Coulomb friction), the pivot stretch against the rigid
// impact model it continues, the sliding stretch's series (sim/reduced/slide_motion.h), and the hand-over
// back into a ModelRun (sim/reduced/free_body_run.h).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>

#include "sim/grains/engine_units.h"
#include "sim/scene/fidelity_preset.h"
#include "sim/geometry/shell_outline.h"
#include "sim/model_registry.h"
#include "sim/reduced/free_body.h"
#include "sim/reduced/free_body_run.h"
#include "sim/reduced/reduced_run.h"
#include "sim/reduced/slide_motion.h"
#include "sim/geometry/shell_properties.h"
#include "test_helpers.h"

using namespace polyroll;
using namespace polyroll::models;

namespace {

using geom::kPi;

Scene empty_scene(int sides, double angle_deg) {
    return test::scene_with({{"fill", {{"ratio", 0.0}}}, {"shell", {{"sides", sides}}}, {"ramp", {{"angle_deg", angle_deg}}}});
}

FreeBody body_of(const Scene& s) {
    const ShellProperties sp = shell_properties(s.shell);
    return {shell_outer_polygon_m(s.shell), sp.mass_kg, sp.inertia_kg_m2};
}

RampFrame rules_of(const Scene& s) {
    RampFrame r;
    r.angle_deg = s.ramp.angle_deg;
    r.gravity_m_s2 = s.run.gravity_m_s2;
    r.friction = s.ramp.friction;
    r.end_centre_x_m = 2.0;
    r.time_limit_s = 2.0;
    r.sample_hz = 1000.0;
    r.sample_grid_hz = 1000.0;
    r.rest_speed_m_s = s.run.rest_speed_m_s;
    return r;
}

}  // namespace

TEST_CASE("a shell dropped vertex-first falls as a parabola and lands without bouncing, by Coulomb's law",
          "[models][hopping]") {
    const Scene s = empty_scene(8, 20.0);
    const FreeBody b = body_of(s);
    RampFrame rules = rules_of(s);
    const double g = s.run.gravity_m_s2, theta = 20.0 * kPi / 180.0;
    const double radius = geom::length(b.outer_m[0]), h0 = 0.01;
    // Vertex 1 straight down (tracker.cpp's numbering: a = pi/n - 2 pi/n), 1 cm above the ramp, at rest.
    FreeBodyStart start;
    start.state.pose.angle_rad = -kPi / 8.0;
    start.state.pose.centre_m = {0.5, radius + h0};
    start.release = start.state.pose;
    start.landed_vertex = 0;  // so that landing on vertex 1 is recorded, with its energies
    start.measured.behaviour = Behaviour::running;
    const FreeBodyMotion r = free_body_motion(b, rules, start);
    REQUIRE(!r.unsupported_time_s);
    REQUIRE(!r.measured.impacts.empty());
    const FaceImpact& landing = r.measured.impacts.front();

    // Free fall along the ramp's normal: h0 = g cos(theta) t^2 / 2.
    const double t_land = std::sqrt(2.0 * h0 / (g * std::cos(theta)));
    CHECK(landing.time_s == Approx(t_land).epsilon(1e-8));
    // The flight is exact: the rows before the landing lie on the parabola.
    for (size_t i = 0; i < r.states.size() && r.measured.trajectory[i].time_s < t_land; ++i) {
        const double t = r.measured.trajectory[i].time_s;
        CHECK(r.states[i].pose.centre_m.x == Approx(0.5 + 0.5 * g * std::sin(theta) * t * t).epsilon(1e-12));
        CHECK(r.states[i].pose.centre_m.y == Approx(radius + h0 - 0.5 * g * std::cos(theta) * t * t).epsilon(1e-12));
        CHECK(r.states[i].angular_velocity_rad_s == 0.0);
    }
    // At the landing the vertex sticks (the friction needed, tan(theta) / (1 + M R^2 / I) of the normal
    // impulse, is under 0.9) and no bounce: the normal velocity is lost, and of the tangential one
    // the energy 1/2 v_t^2 / k with k = 1/M + R^2/I, the vertex's inverse mass along the ramp.
    const double v = g * t_land, vt = v * std::sin(theta), vn = v * std::cos(theta);
    const double k = 1.0 / b.mass_kg + radius * radius / b.inertia_kg_m2;
    CHECK(landing.kinetic_before_J == Approx(0.5 * b.mass_kg * v * v).epsilon(1e-7));
    CHECK(landing.kinetic_after_J == Approx(0.5 * b.mass_kg * (vt * vt + vn * vn) - 0.5 * b.mass_kg * vn * vn -
                                            0.5 * vt * vt / k)
                                         .epsilon(1e-7));

    // With a frictionless ramp the tangential momentum is kept and the vertex slides on.
    rules.friction = 0.0;
    const FreeBodyMotion slick = free_body_motion(b, rules, start);
    REQUIRE(!slick.measured.impacts.empty());
    CHECK(slick.measured.impacts.front().kinetic_after_J == Approx(0.5 * b.mass_kg * vt * vt).epsilon(1e-7));
    CHECK(slick.slides >= 1);
}

TEST_CASE("on a shell that never lifts off, the free rigid body rolls exactly as the rigid impact model",
          "[models][hopping]") {
    // Started at release, it turns about each vertex in turn (sticking: the friction needed, 0.22-0.29
    // of the normal force, is under the ramp's 0.9) and lands every face as the rigid model does.
    for (const auto& [sides, angle] : {std::pair{8, 10.0}, std::pair{18, 5.0}}) {
        INFO("n = " << sides << " at " << angle << " deg");
        const Scene rigid_scene = test::with_model(empty_scene(sides, angle), Model::rigid);
        const RunResult rigid = run_scene(rigid_scene);
        REQUIRE(rigid.model_valid);
        ReducedRun at_release(rigid_scene, FillMotion::frozen);
        FreeBodyRun free_body(rigid_scene, at_release.hand_over());
        free_body.run_to_end();
        const RunResult f = free_body.result();
        CHECK(f.measured.behaviour == rigid.measured.behaviour);
        REQUIRE(f.measured.impacts.size() == rigid.measured.impacts.size());
        for (size_t i = 0; i < f.measured.impacts.size(); ++i) {
            CHECK(f.measured.impacts[i].time_s == Approx(rigid.measured.impacts[i].time_s).margin(1e-6));
            CHECK(f.measured.impacts[i].kinetic_after_J ==
                  Approx(rigid.measured.impacts[i].kinetic_after_J).epsilon(1e-6));
        }
        REQUIRE(f.measured.terminal_velocity_m_s);
        CHECK(*f.measured.terminal_velocity_m_s == Approx(*rigid.measured.terminal_velocity_m_s).epsilon(1e-6));
        CHECK(free_body.run().flights == 0);
    }
}

TEST_CASE("the free rigid body hands over mid-run with the state it shows", "[models][hopping][handover]") {
    // From the rigid model's lift-off on an empty hexagon at 30 deg; stepped part-way, the hand-over
    // carries the pose drawn at that step, and a grain run continues from it.
    const Scene s = test::with_model(empty_scene(6, 30.0), Model::grains);
    ReducedRun rigid(test::with_model(s, Model::rigid), FillMotion::frozen, true);
    const long lift = static_cast<long>(std::floor(*rigid.result().model_invalid_time_s * s.fidelity.step_hz));
    while (rigid.steps() < lift && rigid.step()) {
    }
    FreeBodyRun free_body(s, rigid.hand_over());
    CHECK(free_body.steps() == lift);
    for (int i = 0; i < 150; ++i) free_body.step();
    const HandOver h = free_body.hand_over();
    const RunSnapshot snap = free_body.snapshot();
    CHECK(h.steps == lift + 150);
    CHECK(h.shell.pose.centre_m.x == snap.shell_centre_m.x);
    CHECK(h.shell.pose.angle_rad == snap.shell_angle_rad);
    CHECK(h.measured.trajectory.size() == free_body.measured().trajectory.size());
    std::unique_ptr<ModelRun> grains = continue_run(s, h);
    CHECK(grains->time_s() == Approx(free_body.time_s()));
    CHECK(grains->snapshot().now.position_m == Approx(snap.now.position_m).margin(1e-6));
    CHECK(grains->snapshot().now.potential_J == Approx(snap.now.potential_J).margin(1e-6));
    while (grains->step()) {
    }
    CHECK(grains->measured().behaviour == Behaviour::rolled_to_end);
}

TEST_CASE("a sliding vertex's series follows its equations of motion and keeps energy without friction",
          "[models][hopping][slide]") {
    // The hexagon of the default scene, sliding down the 20-degree ramp on a vertex 30 degrees below
    // its centre's level, turning at 3 rad/s, with friction against the slip and without.
    const Scene scene = empty_scene(6, 20.0);
    const ShellProperties sp = shell_properties(scene.shell);
    const double theta = 20.0 * kPi / 180.0, g = scene.run.gravity_m_s2;
    SlideBody b;
    b.radius_m = sp.outer_circumradius_m;
    b.inv_mass_per_kg = 1.0 / sp.mass_kg;
    b.inv_inertia = 1.0 / sp.inertia_kg_m2;
    b.gravity_along_m_s2 = g * std::sin(theta);
    b.gravity_normal_m_s2 = g * std::cos(theta);
    const double phi0 = -kPi / 2.0 - kPi / 6.0, omega0 = 3.0, x0 = 0.1, vx0 = 0.4;

    // The same equations, written out from slide_motion.h and stepped by classical Runge-Kutta at
    // 10 us: [phi, omega, x, vx].
    using Y = std::array<double, 4>;
    auto rate = [&](const Y& y) {
        const double c = std::cos(y[0]), s = std::sin(y[0]), r = b.radius_m, f = b.friction_ratio;
        const double n = (r * y[1] * y[1] * s + b.gravity_normal_m_s2) /
                         (b.inv_mass_per_kg + r * r * c * (c - f * s) * b.inv_inertia);
        return Y{y[1], n * r * (c - f * s) * b.inv_inertia, y[3], b.gravity_along_m_s2 + f * n * b.inv_mass_per_kg};
    };
    auto integrate = [&](double t_end) {
        Y y{phi0, omega0, x0, vx0};
        const int steps = static_cast<int>(std::lround(t_end / 1e-5));
        const double h = t_end / steps;
        auto plus = [](Y a, const Y& d, double k) {
            for (size_t i = 0; i < 4; ++i) a[i] += k * d[i];
            return a;
        };
        for (int i = 0; i < steps; ++i) {
            const Y k1 = rate(y), k2 = rate(plus(y, k1, h / 2)), k3 = rate(plus(y, k2, h / 2)), k4 = rate(plus(y, k3, h));
            for (size_t j = 0; j < 4; ++j) y[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
        }
        return y;
    };

    for (double f : {-0.9, 0.0, 0.9}) {
        b.friction_ratio = f;
        const SlideSeries ss(b, phi0, omega0, x0, vx0);
        const double t = std::min(0.02, 0.9 * ss.accurate_step_s());
        REQUIRE(t > 0.005);  // the series covers a useful stretch, not a sliver
        const SlideSeries::Point p = ss.at(t);
        const Y y = integrate(t);
        CHECK(p.phi == Approx(y[0]).margin(1e-10));
        CHECK(p.omega == Approx(y[1]).margin(1e-8));
        CHECK(p.x_m == Approx(y[2]).margin(1e-10));
        CHECK(p.vx_m_s == Approx(y[3]).margin(1e-8));
        CHECK(p.sin_phi == Approx(std::sin(p.phi)).margin(1e-12));
        CHECK(p.cos_phi == Approx(std::cos(p.phi)).margin(1e-12));
        if (f == 0.0) {
            // Without friction the ramp's force is normal to the vertex's path: no work.
            auto energy = [&](const SlideSeries::Point& q) {
                const double vy = -q.omega * b.radius_m * q.cos_phi, y_c = -b.radius_m * q.sin_phi;
                return 0.5 * sp.mass_kg * (q.vx_m_s * q.vx_m_s + vy * vy) + 0.5 * sp.inertia_kg_m2 * q.omega * q.omega +
                       sp.mass_kg * (-b.gravity_along_m_s2 * q.x_m + b.gravity_normal_m_s2 * y_c);
            };
            const double e0 = energy(ss.at(0.0));
            for (int i = 0; i <= 20; ++i) CHECK(energy(ss.at(t * i / 20.0)) == Approx(e0).margin(1e-12));
        }
    }
}

TEST_CASE("an empty shell's Box2D works in millimetres where the step allows, and lands as the free body does",
          "[models][hopping][units]") {
    // Box2D holds each polygon a skin (0.01 units) outside its outline: 0.2 mm between shell and ramp
    // at 1 cm, which rounds the corners a hopping shell lands on (docs/studies/free-body-against-box2d.md).
    CHECK(choose_engine_units(empty_scene(6, 30.0)).units_per_m == 100.0);  // standard: 1 mm would cap at 2 m/s
    const Scene box2d = at_finest_box2d(empty_scene(6, 30.0));
    REQUIRE(choose_engine_units(box2d).units_per_m == 1000.0);

    // A landing of the hexagon 2.13 s after release, from the free body's state 1 ms before it: the
    // energy Box2D's landing takes matches the free body's impulse law to 0.3% (at 1 cm Box2D took
    // 0.6% less here; at 1 mm 0.1%).
    Scene s = box2d;
    s.run.model = Model::automatic;
    const ShellProperties shell = shell_properties(s.shell);
    const double th = s.ramp.angle_deg * kPi / 180.0, g = s.run.gravity_m_s2;
    auto energy_J = [&](const ShellState& st) {
        const geom::Vec2 v = st.velocity_m_s;
        return 0.5 * shell.mass_kg * (v.x * v.x + v.y * v.y) +
               0.5 * shell.inertia_kg_m2 * st.angular_velocity_rad_s * st.angular_velocity_rad_s +
               shell.mass_kg * g * (st.pose.centre_m.y * std::cos(th) - st.pose.centre_m.x * std::sin(th));
    };
    long landing = -1;
    {
        auto run = start_run(s);
        double before = energy_J(run->hand_over().shell);
        while (landing < 0 && run->step()) {
            const double now = energy_J(run->hand_over().shell);
            if (run->time_s() > 2.13 && before - now > 1e-5) landing = run->steps();
            before = now;
        }
    }
    REQUIRE(landing > 0);
    auto free_body = start_run(s);
    while (free_body->steps() < landing - 10 && free_body->step()) {
    }
    const HandOver from = free_body->hand_over();
    auto engine = continue_run(box2d, from);
    while (free_body->steps() < landing + 20 && free_body->step()) {
    }
    while (engine->steps() < landing + 20 && engine->step()) {
    }
    const double e0 = energy_J(from.shell);
    const double lost_free_J = e0 - energy_J(free_body->hand_over().shell);
    const double lost_box2d_J = e0 - energy_J(engine->hand_over().shell);
    REQUIRE(lost_free_J > 1e-3);
    CHECK(lost_box2d_J == Approx(lost_free_J).epsilon(0.003));
}

TEST_CASE("the free rigid body's dense output is the run sampled at every step", "[models][hopping]") {
    // Flights, landings and contact stretches of an empty hexagon from the rigid model's lift-off at
    // 30 deg: the row of any step from a run sampled at the scene's rate equals, to the last bit, the
    // row a run sampled at every step records (what drawing and a hand-over once ran a second time for).
    const Scene s = test::with_model(empty_scene(6, 30.0), Model::rigid);
    ReducedRun rigid(s, FillMotion::frozen, true);
    const long lift = static_cast<long>(std::floor(*rigid.result().model_invalid_time_s * s.fidelity.step_hz));
    while (rigid.steps() < lift && rigid.step()) {
    }
    const HandOver h = rigid.hand_over();
    const double hz = s.fidelity.step_hz;
    FreeBodyStart start = free_body_start(h, hz);
    start.measured = Measurements{};  // no records so far: every row below is the free body's own
    start.measured.behaviour = Behaviour::running;
    const FreeBody b = body_of(s);
    RampFrame every_step = rules_of(s);
    every_step.sample_hz = hz;
    every_step.sample_grid_hz = hz;
    RampFrame coarse = every_step;
    coarse.sample_hz = 30.0;
    const FreeBodyMotion fine = free_body_motion(b, every_step, start);
    const FreeBodyMotion run = free_body_motion(b, coarse, start);
    // Row k of the fine run is step k (those before the start hold the start's state).
    REQUIRE(fine.states.size() > static_cast<size_t>(h.steps) + 100);
    CHECK(run.measured.impacts.size() == fine.measured.impacts.size());
    CHECK(run.flights > 0);
    for (size_t i = static_cast<size_t>(h.steps); i < fine.states.size() + 5; ++i) {
        const long step = static_cast<long>(i);
        const std::optional<FreeBodyRow> r = run.row_at_step(step, hz, h.steps);
        REQUIRE(r);
        const size_t j = std::min(i, fine.states.size() - 1);
        INFO("step " << step);
        CHECK(r->state.pose.centre_m.x == fine.states[j].pose.centre_m.x);
        CHECK(r->state.pose.centre_m.y == fine.states[j].pose.centre_m.y);
        CHECK(r->state.pose.angle_rad == fine.states[j].pose.angle_rad);
        CHECK(r->state.angular_velocity_rad_s == fine.states[j].angular_velocity_rad_s);
        CHECK(r->sample.time_s == fine.measured.trajectory[j].time_s);
        CHECK(r->sample.potential_J == fine.measured.trajectory[j].potential_J);
        CHECK(r->landed_vertex == fine.landed_vertices[j]);
    }
}
