// `--model auto`: the registry's rule, a filled shell computed exactly as
// the grain model computes it, and an empty shell run by the rigid model, then from lift-off by the
// free rigid body, then (only where that meets a contact it does not model) by Box2D, the records
// carrying on across each hand-over; measured against the grain model on the empty shells `bench --auto` times.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "sim/registry/auto_run.h"
#include "sim/model_registry.h"
#include "sim/reduced/reduced_models.h"
#include "sim/files/results_io.h"
#include "sim/run_snapshot.h"
#include "sweep/scene_matrices.h"
#include "test_helpers.h"

using namespace polyroll;
using json = nlohmann::ordered_json;

using polyroll::test::with_model;

namespace {

Scene empty_auto_scene(int sides, double angle_deg) {
    Scene s = test::scene_with({{"fill", {{"ratio", 0.0}}},
                                {"shell", {{"sides", sides}}},
                                {"ramp", {{"angle_deg", angle_deg}}},
                                {"run", {{"model", "auto"}}}});
    return s;
}

}  // namespace

TEST_CASE("auto picks the rigid model for an empty shell and grains for a filled one, and says why", "[models][auto]") {
    const ModelChoice empty = choose_model(test::scene_with({{"fill", {{"ratio", 0.0}}}}));
    CHECK(empty.model == Model::rigid);
    REQUIRE(empty.then);
    CHECK(*empty.then == Model::grains);
    CHECK(empty.reason.find("empty shell") != std::string::npos);
    const ModelChoice filled = choose_model(test::scene_with({{"fill", {{"ratio", 0.25}}}}));
    CHECK(filled.model == Model::grains);
    CHECK(!filled.then);
    CHECK(filled.reason.find("trade study") != std::string::npos);
    CHECK(model_named("auto") == Model::automatic);
    CHECK(to_string(Model::automatic) == "auto");
    // auto is a rule over the models, not one of them: compare and bench do not list it.
    for (Model m : all_models()) CHECK(m != Model::automatic);
}

TEST_CASE("auto runs a full shell as one rigid polygon and says why", "[models][auto]") {
    const ModelChoice full = choose_model(test::scene_with({{"fill", {{"ratio", 1.0}}}}));
    CHECK(full.model == Model::rigid);
    REQUIRE(full.then);
    CHECK(*full.then == Model::grains);
    CHECK(full.reason.find("full shell") != std::string::npos);
    // Nearly full is not full: the grains have room to move.
    CHECK(choose_model(test::scene_with({{"fill", {{"ratio", 0.99}}}})).model == Model::grains);
}

TEST_CASE("full shells show only the first two behaviours like solid polygons", "[runs][models][auto]") {
    // The empty-and-full observation's grid (assets/experiment.json) and 4 degrees, full only.
    for (const char* shell : {"hexagon-small", "octagon-small", "decagon-small", "octadecagon-small"}) {
        for (double angle : {4.0, 8.0, 12.0, 16.0, 20.0, 24.0}) {
            const RunResult r =
                run_scene(test::scene_with({{"shell", shell}, {"fill", {{"ratio", 1.0}}}, {"ramp", {{"angle_deg", angle}}}}));
            INFO(shell << " at " << angle << " deg: " << to_string(r.measured.behaviour) << " " << r.measured.divergence);
            CHECK((r.measured.behaviour == Behaviour::stopped_at_first_impact ||
                   r.measured.behaviour == Behaviour::rolled_to_end));
            CHECK(r.measured.max_energy_gain_J < 1e-6);
        }
    }
}

TEST_CASE("the free rigid body of a full shell carries its fill", "[runs][models][auto]") {
    // 24 degrees: the full octagon leaves the ramp and flies as the free body; its mass and the fill
    // reported are the rigid model's, shell and fill together.
    const Scene s = test::scene_with({{"shell", "octagon-small"}, {"fill", {{"ratio", 1.0}}}, {"ramp", {{"angle_deg", 24.0}}}});
    const RunResult r = run_scene(s);
    REQUIRE(r.model_choice);
    REQUIRE(r.model_choice->lift_off_time_s);
    const RunResult frozen = run_scene(test::with_model(s, Model::rigid));
    CHECK(frozen.fill_mass_kg > 0.1);
    CHECK(r.fill_mass_kg == Approx(frozen.fill_mass_kg).epsilon(1e-9));
    // Energy kept across the hand-over to the free body: the potential counts the fill's weight.
    CHECK(r.measured.max_energy_gain_J < 1e-6);
}

TEST_CASE("auto on a filled shell computes exactly what the grain model computes", "[runs][models][auto]") {
    const Scene grains = test::scene_with({{"fill", {{"ratio", 0.25}}}, {"run", {{"time_limit_s", 0.5}}}});
    const RunResult g = run_scene(grains);
    const RunResult a = run_scene(with_model(grains, Model::automatic));
    CHECK(trajectory_csv(a) == trajectory_csv(g));
    CHECK(impacts_csv(a) == impacts_csv(g));
    json ja = summary_json(a), jg = summary_json(g);
    REQUIRE(ja["results"].contains("model_choice"));
    CHECK(ja["results"]["model_choice"]["model"] == "grains");
    CHECK(ja["results"]["model_choice"]["hand_over_time_s"].is_null());
    CHECK(ja["scene"]["run"]["model"] == "auto");
    for (json* j : {&ja, &jg}) {
        (*j)["results"].erase("wall_time_s");
        (*j)["results"].erase("model_choice");
        (*j)["results"].erase("model");
        (*j)["scene"]["run"].erase("model");
    }
    CHECK(ja == jg);
}

TEST_CASE("auto on an empty shell that lifts off carries it on as a free rigid body, records carrying on",
          "[runs][models][handover][auto]") {
    const Scene s = empty_auto_scene(8, 30.0);
    // Where the rigid model stops holding by auto's rule: lift-off, or a slip (the ramp's friction).
    const RunResult rigid = models::run_reduced_model(with_model(s, Model::rigid), models::FillMotion::frozen, true);
    REQUIRE(rigid.model_invalid_time_s);
    const double lift_off_s = *rigid.model_invalid_time_s;
    CHECK(lift_off_s <= *run_scene(with_model(s, Model::rigid)).model_invalid_time_s);

    AutoRun run(s);
    CHECK(!run.choice().lift_off_time_s);
    std::vector<FaceImpact> before;
    while (run.step() && !run.choice().lift_off_time_s) before = run.measured().impacts;
    REQUIRE(run.choice().lift_off_time_s);
    const double t = *run.choice().lift_off_time_s;
    // The last tracker step at which the rigid model still holds.
    CHECK(t <= lift_off_s);
    CHECK(t > lift_off_s - run.step_s() - 1e-12);
    // The impacts landed before are kept as they were.
    REQUIRE(run.measured().impacts.size() >= before.size());
    for (size_t i = 0; i < before.size(); ++i) {
        CHECK(run.measured().impacts[i].time_s == before[i].time_s);
        CHECK(run.measured().impacts[i].position_m == before[i].position_m);
        CHECK(run.measured().impacts[i].kinetic_after_J == before[i].kinetic_after_J);
    }
    // Drawn on the way: the shell leaves the ramp (its lowest vertex above it) at some step.
    double highest_lowest_vertex_m = 0.0;
    while (run.step()) {
        const RunSnapshot snap = run.snapshot();
        double lowest = 1e9;
        for (const geom::Vec2& v : snap.outer_local_m)
            lowest = std::min(lowest, snap.shell_centre_m.y + geom::rotate(v, snap.shell_angle_rad).y);
        CHECK(lowest > -1e-9);  // never into the ramp
        highest_lowest_vertex_m = std::max(highest_lowest_vertex_m, lowest);
    }
    CHECK(highest_lowest_vertex_m > 1e-4);

    const RunResult r = run.result();
    CHECK(r.measured.behaviour == Behaviour::rolled_to_end);
    CHECK(r.model_valid);
    CHECK(!r.model_choice->hand_over_time_s);  // no Box2D world was built
    CHECK(model_that_ran(r) == Model::rigid);
    const json j = summary_json(r);
    CHECK(!j.contains("engine"));
    CHECK(j["results"]["model_choice"]["lift_off_time_s"].get<double>() == Approx(t));
    CHECK(j["results"]["model_choice"]["hand_over_time_s"].is_null());
    const Measurements& m = r.measured;
    for (size_t i = 1; i < m.trajectory.size(); ++i) CHECK(m.trajectory[i].time_s > m.trajectory[i - 1].time_s);
    for (size_t i = 0; i < m.impacts.size(); ++i) CHECK(m.impacts[i].index == static_cast<int>(i) + 1);
    for (size_t i = 1; i < m.impacts.size(); ++i) CHECK(m.impacts[i].position_m > m.impacts[i - 1].position_m);
    // The energy books: nothing is made, only lost (impacts, sliding).
    CHECK(m.max_energy_gain_J <= 1e-12);
    for (size_t i = 1; i < m.trajectory.size(); ++i)
        CHECK(m.trajectory[i].dissipated_J >= m.trajectory[i - 1].dissipated_J - 1e-12);

    // run_scene goes the same way as stepping.
    const RunResult whole = run_scene(s);
    CHECK(trajectory_csv(whole) == trajectory_csv(r));
    CHECK(impacts_csv(whole) == impacts_csv(r));
}

TEST_CASE("auto hands a shell to Box2D at the step before a contact the free rigid body does not model",
          "[runs][models][handover][auto]") {
    // A triangle released on a vertex at 20 deg sets its next face down flat on both vertices.
    const Scene s = empty_auto_scene(3, 20.0);
    AutoRun run(s);
    run.run_to_end();
    const RunResult r = run.result();
    REQUIRE(r.model_choice);
    const ModelChoice& c = *r.model_choice;
    REQUIRE(c.lift_off_time_s);
    REQUIRE(c.hand_over_time_s);
    CHECK(c.hand_over_why == "a face set down on both its vertices at once");
    CHECK(*c.hand_over_time_s >= *c.lift_off_time_s);
    CHECK(model_that_ran(r) == Model::grains);
    CHECK(summary_json(r).contains("engine"));
    CHECK(r.measured.behaviour == run_scene(with_model(s, Model::grains)).measured.behaviour);
    const Measurements& m = r.measured;
    for (size_t i = 1; i < m.trajectory.size(); ++i) CHECK(m.trajectory[i].time_s > m.trajectory[i - 1].time_s);
}

TEST_CASE("auto hands the rigid model's shell on where it would slip, not only where it would lift off",
          "[runs][models][handover][auto]") {
    // The empty hexagon at 20 deg never lifts off, but just before each impact its no-slip rolling
    // needs a friction force 16.7 times the normal force (docs/guide.md, polyroll bench --auto): the ramp's
    // 0.9 cannot give it, and the free rigid body takes over there, sliding, with no Box2D.
    const Scene s = empty_auto_scene(6, 20.0);
    const Scene rigid = with_model(s, Model::rigid);
    CHECK(run_scene(rigid).model_valid);
    const RunResult until = models::run_reduced_model(rigid, models::FillMotion::frozen, true);
    REQUIRE(until.model_invalid_time_s);
    const RunResult a = run_scene(s);
    REQUIRE(a.model_choice);
    REQUIRE(a.model_choice->lift_off_time_s);
    CHECK(*a.model_choice->lift_off_time_s <= *until.model_invalid_time_s);
    CHECK(*a.model_choice->lift_off_time_s > *until.model_invalid_time_s - 1.0 / s.fidelity.step_hz - 1e-12);
    CHECK(!a.model_choice->hand_over_time_s);
    CHECK(a.measured.behaviour == Behaviour::rolled_to_end);
    // With a ramp that grips (friction 2.0, the allowed maximum) the needed 16.7 is still too much.
    Scene grippy = rigid;
    grippy.ramp.friction = 2.0;
    CHECK(models::run_reduced_model(grippy, models::FillMotion::frozen, true).model_invalid_time_s);
}

TEST_CASE("auto on an empty shell that never lifts off is the rigid model throughout", "[runs][models][auto]") {
    const Scene s = empty_auto_scene(8, 5.0);
    const RunResult a = run_scene(s);
    REQUIRE(a.model_choice);
    CHECK(!a.model_choice->hand_over_time_s);
    CHECK(model_that_ran(a) == Model::rigid);
    const RunResult rigid = run_scene(with_model(s, Model::rigid));
    CHECK(trajectory_csv(a) == trajectory_csv(rigid));
    CHECK(impacts_csv(a) == impacts_csv(rigid));
    CHECK(!summary_json(a).contains("engine"));
}

// auto's measure on the empty shells `bench --auto` times: the same behaviour as the grain model everywhere.
TEST_CASE("auto on the empty shells of bench --auto behaves as the grain model does", "[models][auto]") {
    for (const auto& [sides, angle] : scenes::auto_shells()) {
        INFO("n = " << sides << " at " << angle << " deg");
        const Scene s = empty_auto_scene(sides, angle);
        const RunResult a = run_scene(s);
        const RunResult g = run_scene(with_model(s, Model::grains));
        CHECK(a.measured.behaviour == g.measured.behaviour);
        CHECK(a.measured.terminal_velocity_m_s.has_value() == g.measured.terminal_velocity_m_s.has_value());
    }
}
