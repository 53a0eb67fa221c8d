// The calibration's objective and inputs: each check's miss in tolerances (continuous where the check
// allows), their summed squares, measured numbers in observations files, and --params' fields and bounds.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim/errors.h"
#include "sim/scene/scene_json.h"
#include "sweep/calibration.h"
#include "sweep/calibration_params.h"
#include "sweep/observations.h"
#include "sweep/scorecard.h"
#include "test_helpers.h"

using namespace polyroll;
using namespace polyroll::sweep;
using json = nlohmann::ordered_json;

namespace {

ScoredRun rolled(double terminal_velocity_m_s, double distance_m = 2.5) {
    ScoredRun r;
    r.ok = true;
    r.behaviour = "rolled_to_end";
    r.distance_m = distance_m;
    r.terminal_velocity_m_s = terminal_velocity_m_s;
    r.label = "p";
    return r;
}

Observation measured(double terminal_velocity_m_s, double tolerance_m_s) {
    Observation ob;
    ob.id = "lab";
    ob.terminal_velocity_m_s = terminal_velocity_m_s;
    ob.terminal_velocity_tolerance_m_s = tolerance_m_s;
    return ob;
}

json lab_doc(const json& observed, const json& tolerance) {
    return json{{"observations",
                 json::array({json{{"id", "lab"}, {"source", "a lab"}, {"scene", {{"ramp", {{"angle_deg", 25}}}}},
                                   {"observed", observed}, {"tolerance", tolerance}}})}};
}

// The message a lab's observations file is refused with; "" if it is read.
std::string lab_error_of(const json& doc) {
    return test::input_error_of([&] { parse_observations(doc, "lab.json"); });
}

}  // namespace

TEST_CASE("objective: a measured mean misses by its distance in tolerances, signed", "[calibration]") {
    const ObservationScore s = score_observation(measured(0.35, 0.01), {rolled(0.37), rolled(0.39)});
    REQUIRE(s.checks.size() == 1);
    CHECK(s.checks[0].check == "terminal velocity");
    CHECK(s.checks[0].miss == Approx(3.0));  // mean 0.38: 0.03 above, three tolerances
    CHECK_FALSE(s.checks[0].agree);
    CHECK(calibration_objective({s}) == Approx(9.0));
    const ObservationScore near = score_observation(measured(0.35, 0.01), {rolled(0.345), rolled(0.351)});
    CHECK(near.checks[0].agree);
    CHECK(near.checks[0].miss == Approx(-0.2));
    // Continuous: a closer mean always scores better.
    CHECK(calibration_objective({near}) < calibration_objective({s}));
}

TEST_CASE("objective: nothing to compare counts as ten tolerances off", "[calibration]") {
    ScoredRun stopped = rolled(0.0);
    stopped.behaviour = "stopped";
    stopped.terminal_velocity_m_s.reset();
    const ObservationScore s = score_observation(measured(0.35, 0.01), {stopped, stopped});
    CHECK(s.checks[0].miss == 10.0);
    CHECK(s.checks[0].simulation == "no value in 2 runs");
    Observation ob;
    ob.id = "d";
    ob.distance_m = 0.5;
    ob.distance_tolerance_m = 0.1;
    CHECK(score_observation(ob, {rolled(0.3, 0.7), rolled(0.3, 0.8)}).checks[0].miss == Approx(2.5));
}

TEST_CASE("objective: a share's shortfall counts in tenths of the runs, nothing when reached", "[calibration]") {
    Observation ob;
    ob.id = "share";
    ob.behaviour = "rolled_to_end";
    ob.behaviour_share = 0.8;
    ScoredRun stopped = rolled(0.0);
    stopped.behaviour = "stopped";
    // 2 of 5 rolled: 0.4 short of 0.8, four tenths.
    CHECK(score_observation(ob, {rolled(1), rolled(1), stopped, stopped, stopped}).checks[0].miss == Approx(4.0));
    CHECK(score_observation(ob, {rolled(1), rolled(1), rolled(1), rolled(1), stopped}).checks[0].miss == 0.0);
}

TEST_CASE("objective: a band's ends miss by degrees in tolerances, no band by the angles' span", "[calibration]") {
    Observation ob;
    ob.id = "band";
    ob.behaviour = "stopped";
    ob.angle_range_deg = std::make_pair(11.0, 15.0);
    ob.angle_tolerance_deg = 1.0;
    ob.slope_relative = 0.3;
    std::vector<ScoredRun> runs;
    for (double a : {10.0, 12.0, 14.0, 16.0}) {
        ScoredRun r = rolled(0.3);
        r.angle_deg = a;
        r.behaviour = (a >= 12 && a <= 14) ? "stopped" : "stopped_at_first_impact";
        runs.push_back(r);
    }
    ObservationScore s = score_observation(ob, runs);
    REQUIRE(s.checks.size() == 2);
    CHECK(s.checks[0].miss == Approx(1.0));   // starts at 12, one degree late
    CHECK(s.checks[1].miss == Approx(-1.0));  // ends at 14, one degree early
    for (ScoredRun& r : runs) r.behaviour = "rolled_to_end";
    s = score_observation(ob, runs);
    CHECK(s.checks[0].miss == 10.0);  // no band: 6 deg of angles is less than the penalty of 10
}

TEST_CASE("observations: measured numbers need their tolerance, and may stand alone", "[calibration][observations]") {
    const ObservationFile f =
        parse_observations(lab_doc({{"terminal_velocity_m_s", 0.35}, {"distance_m", 2.4}},
                                   {{"terminal_velocity_m_s", 0.01}, {"distance_m", 0.05}}),
                           "lab.json");
    REQUIRE(f.observations.size() == 1);
    CHECK(*f.observations[0].terminal_velocity_m_s == 0.35);
    CHECK(f.observations[0].distance_tolerance_m == 0.05);
    CHECK(f.observations[0].behaviour.empty());
    CHECK_THAT(lab_error_of(lab_doc({{"terminal_velocity_m_s", 0.35}}, json::object())),
               Catch::Contains("tolerance.terminal_velocity_m_s is missing"));
    CHECK_THAT(lab_error_of(lab_doc({{"behaviour", "stopped"}}, {{"behaviour_share", 0.5}, {"distance_m", 0.1}})),
               Catch::Contains("tolerance.distance_m") && Catch::Contains("only with observed.distance_m"));
    CHECK_THAT(lab_error_of(lab_doc({{"distance_m", 0.3}}, {{"distance_m", 0.1}, {"behaviour_share", 0.5}})),
               Catch::Contains("tolerance.behaviour_share") && Catch::Contains("only with observed.behaviour"));
    CHECK_THAT(lab_error_of(lab_doc({{"distance_m", -1}}, {{"distance_m", 0.1}})),
               Catch::Contains("observed.distance_m = -1"));
    CHECK_THAT(lab_error_of(lab_doc({{"distance_m", 1}}, {{"distance_m", 0}})), Catch::Contains("m above 0"));
    CHECK_THAT(lab_error_of(lab_doc({{"terminal_velocity", "smooth"}}, json::object())),
               Catch::Contains("or a measured 'distance_m'"));
}

TEST_CASE("calibration params: bounds from --params, the assets, or the field's limits", "[calibration]") {
    const Scene scene = resolve_scene({});
    const ObservationFile obs =
        parse_observations(lab_doc({{"distance_m", 1.0}}, {{"distance_m", 0.1}}), "lab.json");
    const auto p = parse_calibration_params("fill.material.restitution,ramp.friction=0.4:1.0,shell.depth_m", scene, obs);
    REQUIRE(p.size() == 3);
    CHECK(p[0].lo == 0.05);
    CHECK(p[0].hi == 0.8);
    CHECK_THAT(p[0].bounds_from, Catch::StartsWith("assets/calibration.json: "));
    CHECK(p[1].lo == 0.4);
    CHECK(p[1].bounds_from == "--params");
    CHECK(p[2].lo == 0.001);  // shell.depth_m has no entry: its limits, 0.001 to 2 m
    CHECK(p[2].hi == 2.0);
    CHECK(p[2].bounds_from == "the field's limits");
    auto with_start = p;
    set_start_values(with_start, scene, {{"ramp.friction", 0.6}});
    CHECK(with_start[0].start == 0.5);  // the bb preset's restitution
    CHECK(with_start[0].start_from == "the scene");
    CHECK(with_start[1].start == 0.6);
    CHECK(with_start[1].start_from == "--start");
    CHECK_THROWS_WITH(parse_calibration_params("ramp.angle_deg", scene, obs), Catch::Contains("observation 'lab' sets it"));
    CHECK_THROWS_WITH(parse_calibration_params("ramp.restitution=-0.1:0.2", scene, obs),
                      Catch::Contains("outside the field's limits"));
}

TEST_CASE("calibration: candidate values are tidied to 9 significant digits", "[calibration]") {
    CHECK(tidy_value(0.1 + 0.2) == 0.3);
    CHECK(tidy_value(0.7234375) == 0.7234375);
    CHECK(tidy_value(1.0 / 3.0) == 0.333333333);
}
