// The scorecard's logic on hand-made results: behaviour shares, never-seen behaviours and the band of
// an angle-range observation (its ends and D's slope), each agreeing and disagreeing, and the edges.
#include <catch2/catch.hpp>

#include "sweep/scorecard.h"

using namespace polyroll::sweep;

namespace {

ScoredRun run(const std::string& behaviour, double distance_m = 0.0, double angle_deg = 0.0, std::uint64_t seed = 1) {
    ScoredRun r;
    r.ok = true;
    r.behaviour = behaviour;
    r.distance_m = distance_m;
    r.angle_deg = angle_deg;
    r.seed = seed;
    r.label = "p";
    return r;
}

Observation share_observation(const std::string& behaviour, double share) {
    Observation ob;
    ob.id = "share";
    ob.behaviour = behaviour;
    ob.behaviour_share = share;
    return ob;
}

// The octagon's band: 11.0 to 15.2 deg, D = 0.6 theta - 6.61, ends within 1 deg, slope within 30%.
Observation band_observation() {
    Observation ob;
    ob.id = "band";
    ob.behaviour = "stopped";
    ob.angle_range_deg = std::make_pair(11.0, 15.2);
    ob.linear_fit = LinearFit{0.6, -6.61, 0.95, 0.02};
    ob.angle_tolerance_deg = 1.0;
    ob.slope_relative = 0.3;
    return ob;
}

// Three seeds per angle; `stopping` says how many stop after rolling, at D = slope * theta + c.
std::vector<ScoredRun> band_runs(const std::vector<std::pair<double, int>>& stopping, double slope, double c) {
    std::vector<ScoredRun> runs;
    for (const auto& [angle, k] : stopping)
        for (int s = 0; s < 3; ++s) {
            if (s < k)
                runs.push_back(run("stopped", slope * angle + c + 0.01 * s, angle, static_cast<std::uint64_t>(s + 1)));
            else
                runs.push_back(run(angle < 13 ? "stopped_at_first_impact" : "rolled_to_end", angle < 13 ? 0.02 : 2.5,
                                   angle, static_cast<std::uint64_t>(s + 1)));
        }
    return runs;
}

}  // namespace

TEST_CASE("scorecard: a behaviour share agrees at the needed count and not one below", "[scorecard]") {
    const Observation ob = share_observation("rolled_to_end", 0.8);
    std::vector<ScoredRun> runs(4, run("rolled_to_end"));
    runs.push_back(run("stopped_at_first_impact"));
    ObservationScore s = score_observation(ob, runs);
    REQUIRE(s.checks.size() == 1);
    CHECK(s.agree);
    CHECK(s.checks[0].simulation == "4 of 5 seeds rolled_to_end (others: 1 stopped_at_first_impact)");
    CHECK(s.checks[0].by == "needs 4 of 5: 0 to spare");
    CHECK(*s.checks[0].difference == Approx(0.0).margin(1e-12));

    runs[0] = run("stopped");
    s = score_observation(ob, runs);
    CHECK_FALSE(s.agree);
    CHECK(s.checks[0].by == "needs 4 of 5: 1 short");
    CHECK(*s.checks[0].difference == Approx(-0.2));
}

TEST_CASE("scorecard: failed runs count against a share and are named", "[scorecard]") {
    std::vector<ScoredRun> runs(2, run("stopped_at_first_impact"));
    ScoredRun failed;  // failed or missing
    failed.label = "p";
    runs.push_back(failed);
    runs.push_back(failed);
    const ObservationScore s = score_observation(share_observation("stopped_at_first_impact", 0.5), runs);
    CHECK(s.agree);  // 2 of 4 is half: "at least" the share
    CHECK(s.checks[0].simulation == "2 of 4 seeds stopped_at_first_impact (others: 2 failed)");
    CHECK(s.details["failed_runs"] == 2);
}

TEST_CASE("scorecard: a grid's share names its least agreeing point", "[scorecard]") {
    std::vector<ScoredRun> runs = {run("rolled_to_end"), run("rolled_to_end"), run("stopped"), run("rolled_to_end")};
    runs[2].label = runs[3].label = "q";
    const ObservationScore s = score_observation(share_observation("rolled_to_end", 0.5), runs);
    CHECK(s.agree);
    CHECK(s.checks[0].simulation ==
          "3 of 4 runs rolled_to_end (others: 1 stopped); least agreeing point q: 1 of 2 seeds rolled_to_end");
    CHECK(s.details["per_point"].size() == 2);
}

TEST_CASE("scorecard: a behaviour never seen agrees only when no run shows it", "[scorecard]") {
    Observation ob;
    ob.id = "never";
    ob.not_behaviour = "stopped";
    ob.behaviour_share = 1.0;
    std::vector<ScoredRun> runs = {run("rolled_to_end"), run("stopped_at_first_impact"), run("rolled_to_end")};
    ObservationScore s = score_observation(ob, runs);
    CHECK(s.agree);
    CHECK(s.checks[0].simulation == "0 of 3 seeds stopped");
    runs[1] = run("stopped", 0.4);
    s = score_observation(ob, runs);
    CHECK_FALSE(s.agree);
    CHECK(s.checks[0].simulation == "1 of 3 seeds stopped");
    CHECK(s.details["runs_showing"].size() == 1);
}

TEST_CASE("scorecard: the band and D's slope agree when simulated as the paper saw them", "[scorecard]") {
    std::vector<std::pair<double, int>> stopping;
    for (double a = 9; a <= 17; a += 0.5) stopping.emplace_back(a, a >= 11.0 && a <= 15.0 ? 3 : 0);
    const ObservationScore s = score_observation(band_observation(), band_runs(stopping, 0.55, -6.0));
    REQUIRE(s.checks.size() == 3);
    CHECK(s.agree);
    CHECK(s.checks[0].simulation == "11 deg (3 of 3 seeds stopped)");
    CHECK(*s.checks[0].difference == Approx(0.0));
    CHECK(*s.checks[1].difference == Approx(-0.2));
    CHECK(scorecard_csv({s}).find(",-0.2,deg,") != std::string::npos);  // rounded, not -0.1999...
    CHECK(*s.checks[2].difference == Approx(-0.05).margin(1e-9));
    CHECK(s.details["fit"]["slope_m_per_deg"].get<double>() == Approx(0.55));
}

TEST_CASE("scorecard: a band too narrow and too steep disagrees, by how much", "[scorecard]") {
    // As polyroll once showed it: the third behaviour at 13.5-14 deg only, D jumping.
    std::vector<std::pair<double, int>> stopping;
    for (double a = 9; a <= 17; a += 0.5) stopping.emplace_back(a, a == 13.5 ? 2 : a == 14.0 ? 3 : a == 12.5 ? 1 : 0);
    const ObservationScore s = score_observation(band_observation(), band_runs(stopping, 2.0, -26.0));
    CHECK_FALSE(s.agree);
    CHECK_FALSE(s.checks[0].agree);
    CHECK(*s.checks[0].difference == Approx(2.5));
    CHECK(s.checks[0].by == "+2.50 deg: 1.50 beyond the tolerance of 1 deg");
    CHECK(s.checks[1].agree == false);  // 14 vs 15.2: 1.2 off
    CHECK_FALSE(s.checks[2].agree);    // slope 2.0 vs 0.6
    CHECK(s.checks[0].simulation == "13.5 deg (2 of 3 seeds stopped)");  // most seeds: 1 of 3 at 12.5 is not
}

TEST_CASE("scorecard: no third behaviour at any angle, or at one angle only", "[scorecard]") {
    std::vector<std::pair<double, int>> none = {{10, 0}, {12, 1}, {14, 0}};
    ObservationScore s = score_observation(band_observation(), band_runs(none, 0.6, -6.61));
    CHECK_FALSE(s.agree);
    for (const ScoreCheck& c : s.checks) {
        CHECK_FALSE(c.agree);
        CHECK_FALSE(c.difference.has_value());
    }
    CHECK(s.checks[0].by == "no band");

    std::vector<std::pair<double, int>> one = {{10, 0}, {12, 3}, {14, 0}};
    s = score_observation(band_observation(), band_runs(one, 0.6, -6.61));
    CHECK_FALSE(s.agree);
    CHECK(s.checks[0].agree);  // 12 is within 1 deg of 11
    CHECK_FALSE(s.checks[1].agree);
    CHECK(s.checks[2].simulation == "one angle only (12 deg): no slope");
    CHECK_FALSE(s.checks[2].agree);
}

TEST_CASE("scorecard: a gap inside the band is reported", "[scorecard]") {
    std::vector<std::pair<double, int>> gappy = {{10, 0}, {11, 3}, {12, 0}, {13, 3}, {14, 3}, {15, 3}, {16, 0}};
    const ObservationScore s = score_observation(band_observation(), band_runs(gappy, 0.6, -6.0));
    CHECK(s.details["gaps_deg"] == nlohmann::ordered_json::array({12.0}));
    CHECK_THAT(s.checks[1].simulation, Catch::Contains("1 angle(s) inside without it"));
}

TEST_CASE("scorecard: least squares line", "[scorecard]") {
    const auto f = fit_line({{1, 1}, {2, 3}, {3, 5}});
    REQUIRE(f);
    CHECK(f->slope == Approx(2.0));
    CHECK(f->intercept == Approx(-1.0));
    CHECK(f->r_squared == Approx(1.0));
    CHECK_FALSE(fit_line({{1, 1}, {1, 2}}));
    CHECK_FALSE(fit_line({{1, 1}}));
}

TEST_CASE("scorecard: files have one CSV row per check", "[scorecard]") {
    const ObservationScore s = score_observation(share_observation("rolled_to_end", 0.5), {run("rolled_to_end")});
    const std::string csv = scorecard_csv({s});
    CHECK(csv == "observation,check,experiment,simulation,agree,difference,unit,by\n"
                 "share,behaviour share,rolled_to_end in at least 50% of runs,1 of 1 seeds rolled_to_end,yes,0.5,share,"
                 "needs 1 of 1: 0 to spare\n");
    const auto doc = scorecard_json({s}, {{"seeds", 1}});
    CHECK(doc["format"] == "polyroll-scorecard-1");
    CHECK(doc["observations_agreeing"] == 1);
    CHECK(doc["seeds"] == 1);
}

TEST_CASE("scorecard: the JSON holds the experiment as numbers and each run's place, for the figures",
          "[scorecard]") {
    std::vector<ScoredRun> runs = band_runs({{12.0, 3}}, 0.6, -6.61);
    for (ScoredRun& r : runs) {
        r.run_id = "00000000000000" + std::to_string(10 + r.seed);
        r.ramp_length_m = 2.539;
        r.label_without_angle = "";
    }
    const auto doc = scorecard_json({score_observation(band_observation(), runs)}, {});
    const auto& ob = doc["observations"][0];
    CHECK(ob["experiment"]["behaviour"] == "stopped");
    CHECK(ob["experiment"]["angle_range_deg"][1].get<double>() == Approx(15.2));
    CHECK(ob["experiment"]["angle_tolerance_deg"].get<double>() == Approx(1.0));
    CHECK(ob["experiment"]["linear_fit"]["intercept_m"].get<double>() == Approx(-6.61));
    REQUIRE(ob["runs"].size() == 3);
    CHECK(ob["runs"][2]["run_id"] == "0000000000000013");
    CHECK(ob["runs"][2]["angle_deg"].get<double>() == Approx(12.0));
    CHECK(ob["runs"][2]["seed"] == 3);
    CHECK(ob["runs"][2]["ramp_length_m"].get<double>() == Approx(2.539));
    CHECK(ob["runs"][2]["point"] == "p");

    const ObservationScore rolls = score_observation(share_observation("rolled_to_end", 0.8), {run("rolled_to_end")});
    const auto share = scorecard_json({rolls}, {});
    CHECK(share["observations"][0]["experiment"]["behaviour_share"].get<double>() == Approx(0.8));
    CHECK_FALSE(share["observations"][0]["experiment"].contains("angle_range_deg"));
}
