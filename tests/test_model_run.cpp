// The run interface and the model registry: every model starts, steps and ends as run_scene ends it;
// the snapshot is built by the run whatever the model; a run hands over to another model with its
// records carrying on; the per-step force hook is called before every engine step and its forces act.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <box2d/box2d.h>
#include <nlohmann/json.hpp>

#include "sim/errors.h"
#include "sim/model_blocks.h"
#include "sim/model_registry.h"
#include "sim/files/results_io.h"
#include "sim/grains/simulation.h"
#include "sim/grains/world_builder.h"
#include "test_helpers.h"

using namespace polyroll;
using json = nlohmann::ordered_json;

using polyroll::test::with_model;

namespace {

// summary.json without the wall time, which is the only field that is not a function of the scene.
json summary_without_wall_time(const RunResult& r) {
    json j = summary_json(r);
    j["results"].erase("wall_time_s");
    return j;
}

}  // namespace

TEST_CASE("every registered model steps to the end run_scene gives, with a snapshot at each step", "[runs][models]") {
    const Scene base = test::scene_with({{"fill", {{"ratio", 0.25}}}, {"run", {{"time_limit_s", 0.4}}}});
    // The models this file was written against are registered (a new row adds to them; it does not
    // change this test), the reference first.
    for (Model m : {Model::grains, Model::segments, Model::rigid, Model::dem3d})
        CHECK(std::find(all_models().begin(), all_models().end(), m) != all_models().end());
    CHECK(all_models().front() == reference_model());
    // The 3D reference (a minute of Yade a run) has its own tests: tests/test_dem3d.cpp.
    REQUIRE(everyday_models().size() >= 3);
    for (Model m : everyday_models()) {
        INFO("model " << to_string(m));
        const Scene s = with_model(base, m);
        const ModelTraits& traits = model_traits(m);
        std::unique_ptr<ModelRun> run = start_run(s);
        CHECK(run->steps() == 0);
        CHECK(run->time_s() == 0.0);
        CHECK((run->grains() > 0) == traits.has_grains);
        while (run->step()) {
            if (run->steps() % 50 == 0) {
                const RunSnapshot snap = run->snapshot();
                CHECK(snap.time_s == Approx(run->time_s()));
                CHECK(snap.shell_centre_m.y > 0.0);
                CHECK(snap.grains.size() == static_cast<size_t>(run->grains()));
                CHECK(snap.speed_history.back().time_s == Approx(snap.time_s));
            }
        }
        CHECK(run->finished());
        CHECK(run->measured().behaviour != Behaviour::running);
        if (!traits.engine) {
            // A reduced run jumps to its end (ReducedRun::run_to_end): at the step stepping reaches.
            std::unique_ptr<ModelRun> jump = start_run(s);
            jump->run_to_end();
            CHECK(jump->steps() == run->steps());
            CHECK(jump->finished());
        }
        const RunResult whole = run_scene(s);
        CHECK(summary_without_wall_time(run->result()) == summary_without_wall_time(whole));
        CHECK(trajectory_csv(run->result()) == trajectory_csv(whole));
        CHECK(impacts_csv(run->result()) == impacts_csv(whole));
        CHECK(summary_json(whole).contains("engine") == traits.engine);
        CHECK(traits.fill_description.get().empty() == traits.has_grains.get());
    }
}

TEST_CASE("the force hook is called before every engine step and its force moves the shell", "[runs]") {
    // An empty shell resting on a face of a level ramp does not move (test_runs.cpp); pushed down the
    // ramp through the hook harder than friction and its own weight hold it (a hexagon tips over its
    // downhill vertex above g tan(pi/6) = 5.7 m/s^2), it rolls.
    const Scene s = test::scene_with({{"fill", {{"ratio", 0.0}}},
                                      {"ramp", {{"angle_deg", 0.0}}},
                                      {"release", {{"pose", "face"}, {"tilt_deg", 0.0}}},
                                      {"run", {{"time_limit_s", 0.2}}}});
    long calls = 0;
    double step_s = 0.0;
    auto push = [&](SimWorld& w, double engine_step_s) {
        ++calls;
        step_s = engine_step_s;
        const double force_N = 15.0 * w.shell_props.mass_kg;  // 15 m/s^2 down the ramp
        // Box2D's force unit is kg x engine unit / s^2.
        w.shell->ApplyForceToCenter(b2Vec2(static_cast<float>(w.units.to_units(force_N)), 0.0f), true);
    };
    Simulation pushed(s, {push});
    while (pushed.step()) {
    }
    CHECK(calls == pushed.steps() * s.fidelity.substeps);  // no grains: nothing to settle
    CHECK(step_s == Approx(1.0 / (s.fidelity.step_hz * s.fidelity.substeps)));
    CHECK(pushed.measured().distance_m > 0.01);

    Simulation still(s);
    while (still.step()) {
    }
    CHECK(std::fabs(still.measured().distance_m) < 1e-4);
}

TEST_CASE("a grain run handed over to itself carries on its records", "[runs][handover]") {
    // The trivial hand-over: the grain model continues its own run of an empty shell from its state.
    const Scene s = with_model(test::scene_with({{"fill", {{"ratio", 0.0}}}, {"run", {{"time_limit_s", 0.6}}}}),
                               Model::grains);
    std::unique_ptr<ModelRun> first = start_run(s);
    const long at = 300;
    while (first->steps() < at && first->step()) {
    }
    REQUIRE(first->steps() == at);
    const HandOver h = first->hand_over();
    const TrajectorySample before = first->snapshot().now;
    std::unique_ptr<ModelRun> second = continue_run(s, h);
    CHECK(second->steps() == at);
    CHECK(second->time_s() == Approx(0.3));
    const RunSnapshot now = second->snapshot();
    CHECK(now.now.position_m == Approx(before.position_m).margin(1e-6));
    CHECK(now.now.angle_deg == Approx(before.angle_deg).margin(1e-3));
    CHECK(now.now.speed_m_s == Approx(before.speed_m_s).margin(1e-6));
    CHECK(now.now.potential_J == Approx(before.potential_J).margin(1e-9));
    CHECK(now.shell_centre_m.x == Approx(first->snapshot().shell_centre_m.x).margin(1e-6));
    CHECK(now.speed_history.size() == first->snapshot().speed_history.size());

    // Both go on; they agree closely (the new world starts without the old one's contact history).
    while (first->step()) {
    }
    while (second->step()) {
    }
    const Measurements& a = first->measured();
    const Measurements& b = second->measured();
    CHECK(b.behaviour == a.behaviour);
    CHECK(b.impacts.size() == a.impacts.size());
    CHECK(b.distance_m == Approx(a.distance_m).margin(0.01));
    REQUIRE(b.trajectory.size() == a.trajectory.size());
    for (size_t i = 1; i < b.trajectory.size(); ++i) CHECK(b.trajectory[i].time_s > b.trajectory[i - 1].time_s);
    for (size_t i = 0; i < b.impacts.size(); ++i) CHECK(b.impacts[i].index == static_cast<int>(i) + 1);
}

TEST_CASE("an empty shell handed over from the rigid model to the grain simulation rolls on", "[runs][models][handover]") {
    // The rigid model is the exact limit of an empty shell in Box2D: after the hand-over the grain
    // simulation carries on where the rigid model was, at the same position, speed and energy books,
    // and goes on the way the rigid model went.
    const Scene grains = with_model(test::scene_with({{"fill", {{"ratio", 0.0}}},
                                                      {"fidelity", {{"preset", "precise"}}},
                                                      {"run", {{"time_limit_s", 1.0}}}}),
                                    Model::grains);
    const Scene rigid = with_model(grains, Model::rigid);
    std::unique_ptr<ModelRun> a = start_run(rigid);
    const long at = static_cast<long>(std::lround(0.54 * rigid.fidelity.step_hz));
    while (a->steps() < at && a->step()) {
    }
    REQUIRE(a->steps() == at);
    REQUIRE(!a->finished());
    REQUIRE(!a->measured().impacts.empty());
    const HandOver h = a->hand_over();
    const RunSnapshot sa = a->snapshot();
    std::unique_ptr<ModelRun> b = continue_run(grains, h);
    const RunSnapshot sb = b->snapshot();
    CHECK(b->time_s() == Approx(a->time_s()));
    CHECK(sb.shell_centre_m.x == Approx(sa.shell_centre_m.x).margin(1e-6));
    CHECK(sb.shell_centre_m.y == Approx(sa.shell_centre_m.y).margin(3e-4));  // two skins: 0.2 mm at 1 cm units
    CHECK(sb.shell_angle_rad == Approx(sa.shell_angle_rad).margin(1e-6));
    CHECK(sb.now.position_m == Approx(sa.now.position_m).margin(1e-6));
    CHECK(sb.now.speed_m_s == Approx(sa.now.speed_m_s).margin(1e-4));
    CHECK(sb.now.angle_deg == Approx(sa.now.angle_deg).margin(1e-3));
    CHECK(sb.now.kinetic_J == Approx(sa.now.kinetic_J).epsilon(1e-3));
    CHECK(sb.now.potential_J == Approx(sa.now.potential_J).margin(1e-9));
    CHECK(sb.impacts == sa.impacts);

    // One tracker step on, the grain simulation has moved as the rigid model does.
    a->step();
    b->step();
    CHECK(b->snapshot().now.position_m == Approx(a->snapshot().now.position_m).margin(1e-4));

    // To the end: the records run on without a gap and the impacts keep counting.
    while (b->step()) {
    }
    const Measurements& m = b->measured();
    CHECK(m.behaviour != Behaviour::diverged);
    for (size_t i = 1; i < m.trajectory.size(); ++i) CHECK(m.trajectory[i].time_s > m.trajectory[i - 1].time_s);
    for (size_t i = 0; i < m.impacts.size(); ++i) CHECK(m.impacts[i].index == static_cast<int>(i) + 1);
    CHECK(m.impacts.size() > h.measured.impacts.size());
    const RunResult full_rigid = run_scene(rigid);
    CHECK(m.distance_m == Approx(full_rigid.measured.distance_m).epsilon(0.05));
}

TEST_CASE("a reduced model cannot yet carry on another model's run", "[models][handover]") {
    const Scene s = test::scene_with({{"fill", {{"ratio", 0.0}}}});
    std::unique_ptr<ModelRun> a = start_run(s);
    a->step();
    CHECK_THROWS_AS(continue_run(with_model(s, Model::rigid), a->hand_over()), InputError);
}

TEST_CASE("a filled shell handed over from the rigid model pours its grains moving with the shell", "[runs][handover]") {
    // The grains are poured unsettled in the shell's frame at the hand-over pose, moving with it as
    // one rigid body (the rigid model's frozen fill); they settle as the run goes on.
    const Scene grains =
        with_model(test::scene_with({{"fill", {{"ratio", 0.25}}}, {"run", {{"time_limit_s", 0.8}}}}), Model::grains);
    const Scene rigid = with_model(grains, Model::rigid);
    std::unique_ptr<ModelRun> a = start_run(rigid);
    while (a->steps() < 500 && a->step()) {
    }
    REQUIRE(a->steps() == 500);
    std::unique_ptr<ModelRun> b = continue_run(grains, a->hand_over());
    REQUIRE(b->grains() > 0);
    const RunSnapshot s = b->snapshot();
    CHECK(s.now.speed_m_s == Approx(a->snapshot().now.speed_m_s).margin(1e-4));
    while (b->step()) {
    }
    CHECK(b->measured().behaviour != Behaviour::diverged);
    CHECK(b->measured().grains_inside == b->grains());
}

// RunResult::model_blocks holds its JSON behind a pointer (model_blocks.h): it must still behave as a
// value, as the json member it replaced did.
TEST_CASE("model blocks: copies are independent, a moved-from one reads empty and can be written again") {
    ModelBlocks a;
    CHECK(a.json().is_object());
    CHECK(a.json().empty());
    a.json()["engine"]["units_per_m"] = 100.0;
    ModelBlocks b = a;
    b.json()["engine"]["units_per_m"] = 1000.0;
    CHECK(a.json()["engine"]["units_per_m"] == 100.0);
    ModelBlocks c = std::move(a);
    CHECK(c.json()["engine"]["units_per_m"] == 100.0);
    const ModelBlocks& moved_from = a;
    CHECK(moved_from.json().empty());
    a.json()["dem3d_engine"]["threads"] = 1;
    CHECK(a.json().size() == 1);
    c = b;
    CHECK(c.json()["engine"]["units_per_m"] == 1000.0);
    CHECK(b.json()["engine"]["units_per_m"] == 1000.0);
    b = std::move(c);
    CHECK(b.json()["engine"]["units_per_m"] == 1000.0);
}
