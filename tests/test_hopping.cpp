// The free rigid body that carries an empty shell on after lift-off (models/hopping_polygon.h):
// exact flight, the impact law (no bounce, Coulomb friction), the pivot stretch against the rigid
// impact model it continues, and the hand-over back into a ModelRun (models/hopping_run.h).
#include <catch2/catch.hpp>

#include <cmath>

#include "sim/fill_plan.h"
#include "sim/model_registry.h"
#include "sim/models/hopping_polygon.h"
#include "sim/models/hopping_run.h"
#include "sim/models/reduced_run.h"
#include "sim/shell_properties.h"
#include "test_helpers.h"

using namespace polyroll;
using namespace polyroll::models;

namespace {

constexpr double kPi = geom::kPi;

Scene empty_scene(int sides, double angle_deg) {
    return test::scene_with({{"fill", {{"ratio", 0.0}}}, {"shell", {{"sides", sides}}}, {"ramp", {{"angle_deg", angle_deg}}}});
}

HopBody body_of(const Scene& s) {
    const ShellProperties sp = shell_properties(s.shell);
    return {shell_outer_polygon_m(s.shell), sp.mass_kg, sp.inertia_kg_m2};
}

HopRules rules_of(const Scene& s) {
    HopRules r;
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
    const HopBody b = body_of(s);
    HopRules rules = rules_of(s);
    const double g = s.run.gravity_m_s2, theta = 20.0 * kPi / 180.0;
    const double radius = geom::length(b.outer_m[0]), h0 = 0.01;
    // Vertex 1 straight down (tracker.cpp's numbering: a = pi/n - 2 pi/n), 1 cm above the ramp, at rest.
    HopStart start;
    start.state.pose.angle_rad = -kPi / 8.0;
    start.state.pose.centre_m = {0.5, radius + h0};
    start.release = start.state.pose;
    start.landed_vertex = 0;  // so that landing on vertex 1 is recorded, with its energies
    start.measured.behaviour = Behaviour::running;
    const HopRun r = hop(b, rules, start);
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
    const HopRun slick = hop(b, rules, start);
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
        HoppingRun free_body(rigid_scene, at_release.hand_over());
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
    HoppingRun free_body(s, rigid.hand_over());
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
