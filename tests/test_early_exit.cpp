// Calibrate's early exit (docs/calibrate.md, "Runs that end when their observation is decided"): a
// run with run.end_at_impact ends at that face impact, says so, and measures what it measured up to
// there exactly as the whole run; the plan sets it only on runs whose every observation is decided there.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "sim/geometry/shell_outline.h"
#include "sim/geometry/shell_pose.h"
#include "sim/geometry/shell_properties.h"
#include "sim/model_registry.h"
#include "sim/shell_tracker.h"
#include "sweep/observations.h"
#include "hand_landing.h"
#include "test_helpers.h"

using namespace polyroll;
using namespace polyroll::sweep;
using json = nlohmann::ordered_json;

namespace {

// Vertex 2 of an empty shell landing on the ramp (pointing straight down, approaching, then stopped),
// then three more steps at rest on it, turning so never at rest: the tracker's first face impact at step 3.
Measurements land_once(const Scene& s, long* steps_observed) {
    std::vector<test::LandingRow> rows;
    for (const double h : {3.0, 2.0, 0.5}) rows.push_back({h, 1.0, 1.0, 1.0});
    for (int k = 0; k < 4; ++k) rows.push_back({0.0, 0.0, 1.0, 1.0});
    const test::Landing landing = test::measure_landing(s, rows);
    *steps_observed = landing.steps_observed;
    return landing.measured;
}

}  // namespace

TEST_CASE("early exit: the tracker ends the run at run.end_at_impact and says so", "[tracker][early-exit]") {
    Scene s = test::scene_with({{"fill", {{"ratio", 0.0}}}});
    REQUIRE(s.run.end_at_impact == 0);  // the default: every run to its own end
    long steps = 0;
    SECTION("0: the run goes on past its impacts") {
        const Measurements m = land_once(s, &steps);
        CHECK(m.behaviour == Behaviour::running);
        CHECK(m.impacts.size() == 1);
        CHECK(m.ended_early.empty());
        CHECK(steps == 7);
    }
    SECTION("at the impact asked for, the run ends there: time_limit, with the reason") {
        s.run.end_at_impact = 1;
        const Measurements m = land_once(s, &steps);
        CHECK(steps == 3);  // observe() returned false at the landing's step
        CHECK(m.behaviour == Behaviour::time_limit);
        REQUIRE(m.impacts.size() == 1);
        CHECK(m.end_time_s == m.impacts[0].time_s);
        CHECK(m.ended_early.find("face impact 1 (run.end_at_impact = 1)") != std::string::npos);
        CHECK(m.trajectory.back().time_s == m.end_time_s);  // the last state is in the trajectory
    }
    SECTION("an impact not reached yet does not end it") {
        s.run.end_at_impact = 2;
        const Measurements m = land_once(s, &steps);
        CHECK(m.behaviour == Behaviour::running);
        CHECK(steps == 7);
    }
}

TEST_CASE("early exit: a grain run ended at its second impact measured its start exactly as the whole run",
          "[early-exit]") {
    // A small, quick grain run that rolls past its first impact (the octadecagon at 20 degrees, draft).
    Scene s = test::scene_with({{"shell", "octadecagon-small"},
                                {"fill", {{"ratio", 0.25}}},
                                {"ramp", {{"angle_deg", 20.0}}},
                                {"fidelity", "draft"},
                                {"run", {{"time_limit_s", 1.5}}}});
    const RunResult whole = run_scene(s);
    REQUIRE(whole.measured.impacts.size() >= 3);
    s.run.end_at_impact = 2;
    const RunResult early = run_scene(s);
    const Measurements& m = early.measured;
    CHECK(m.behaviour == Behaviour::time_limit);
    CHECK_FALSE(m.ended_early.empty());
    REQUIRE(m.impacts.size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
        CHECK(m.impacts[i].time_s == whole.measured.impacts[i].time_s);
        CHECK(m.impacts[i].position_m == whole.measured.impacts[i].position_m);
        CHECK(m.impacts[i].kinetic_after_J == whole.measured.impacts[i].kinetic_after_J);
    }
    CHECK(m.end_time_s == m.impacts[1].time_s);
    // Every trajectory row but the last (the state it ended at) is the whole run's.
    REQUIRE(m.trajectory.size() >= 2);
    for (std::size_t i = 0; i + 1 < m.trajectory.size(); ++i) {
        CHECK(m.trajectory[i].time_s == whole.measured.trajectory[i].time_s);
        CHECK(m.trajectory[i].position_m == whole.measured.trajectory[i].position_m);
    }
    CHECK(early.steps < whole.steps);
}

TEST_CASE("early exit: an observation is decided at the second impact only if it asks no more than the first "
          "impact's stop",
          "[observations][early-exit]") {
    const ObservationFile f = read_observations("");
    for (const Observation& ob : f.observations)
        CHECK(decided_at_impact(ob) == (ob.id == "text-below-10-first-impact" ? 2 : 0));
    Observation ob;
    ob.not_behaviour = "stopped_at_first_impact";
    CHECK(decided_at_impact(ob) == 2);
    ob.distance_m = 0.1;  // a measured distance needs the whole run
    CHECK(decided_at_impact(ob) == 0);
    Observation tv;
    tv.behaviour = "stopped_at_first_impact";
    tv.terminal_velocity = "reached smoothly";  // reported: the whole run
    CHECK(decided_at_impact(tv) == 0);
    Observation band;
    band.behaviour = "stopped";
    CHECK(decided_at_impact(band) == 0);
}

TEST_CASE("early exit: calibrate's plan ends only the decided runs early, the same runs otherwise",
          "[observations][early-exit]") {
    const ObservationFile f = read_observations("");
    const ValidationPlan full = make_validation_plan(f, 2, {});
    const ValidationPlan early = make_validation_plan(f, 2, {}, true);
    CHECK(std::find(full.plan.fields.begin(), full.plan.fields.end(), "run.end_at_impact") == full.plan.fields.end());
    CHECK(early.plan.fields.back() == "run.end_at_impact");
    REQUIRE(early.plan.runs.size() == full.plan.runs.size());
    REQUIRE(early.places.size() == full.places.size());
    std::size_t ended = 0;
    for (std::size_t i = 0; i < early.places.size(); ++i) {
        const RunPlace& p = early.places[i];
        CHECK(p.run == full.places[i].run);
        const json& point = early.plan.runs[p.run].point;
        const bool decided = f.observations[p.observation].id == "text-below-10-first-impact";
        CHECK(point.contains("run.end_at_impact") == decided);
        if (decided) CHECK(point["run.end_at_impact"] == 2);
        // The point is the full plan's with that one field more.
        json rest = point;
        rest.erase("run.end_at_impact");
        CHECK(rest == full.plan.runs[p.run].point);
    }
    for (const PlannedRun& r : early.plan.runs) ended += r.point.contains("run.end_at_impact") ? 1 : 0;
    CHECK(ended == 12 * 2);  // the 12 scenes below 10 degrees, 2 seeds each
    // A run shared with an observation that needs the whole run is not ended early.
    json doc = json::parse(R"({"observations": [
        {"id": "a", "source": "s", "scene": {"ramp": {"angle_deg": 8}}, "observed": {"behaviour": "stopped_at_first_impact"},
         "tolerance": {"behaviour_share": 0.5}},
        {"id": "b", "source": "s", "scene": {"ramp": {"angle_deg": 8}}, "observed": {"not_behaviour": "stopped"},
         "tolerance": {"behaviour_share": 1.0}}]})");
    const ValidationPlan shared = make_validation_plan(parse_observations(doc, "obs.json"), 1, {}, true);
    REQUIRE(shared.plan.runs.size() == 1);
    CHECK_FALSE(shared.plan.runs[0].point.contains("run.end_at_impact"));
    // The command line's own value is kept.
    const ValidationPlan own = make_validation_plan(f, 1, {{"run.end_at_impact", 0}}, true);
    for (const PlannedRun& r : own.plan.runs) CHECK(r.point["run.end_at_impact"] == 0);
}
