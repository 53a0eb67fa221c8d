// Reading observations files: the bundled experiment.json, a good hand-made file, its expansion into
// one sweep plan, and bad files refused with one line naming the observation, the key and the value.
#include <catch2/catch.hpp>

#include <set>

#include "sim/errors.h"
#include "sweep/observations.h"
#include "test_helpers.h"

using namespace polyroll::sweep;
using json = nlohmann::ordered_json;

namespace {

json good_doc() {
    return json::parse(R"({
      "observations": [
        { "id": "rolls", "source": "test",
          "scene": { "shell": "hexagon-small", "fill": { "ratio": 0.25, "material": "bb" }, "ramp": { "angle_deg": 20 } },
          "observed": { "behaviour": "rolled_to_end", "terminal_velocity": "smooth" },
          "tolerance": { "behaviour_share": 0.8, "reason": "r" } },
        { "id": "band", "source": "test",
          "scene": { "shell": { "preset": "octagon-small" }, "fill": { "ratio": 0.375 } },
          "angle_range_deg": [11, 15.2],
          "angles_deg": { "from": 10, "to": 16, "step": 2 },
          "observed": { "behaviour": "stopped", "linear_fit": { "slope_m_per_deg": 0.6, "intercept_m": -6.61 } },
          "tolerance": { "angle_range_deg": 1, "slope_relative": 0.3 } },
        { "id": "grid", "source": "test",
          "grid": { "shell.preset": ["hexagon-small", "octagon-small"], "ramp.angle_deg": [18, 20] },
          "scene": { "fill": { "ratio": 0.25, "material": "bb" } },
          "observed": { "not_behaviour": "stopped" },
          "tolerance": { "behaviour_share": 1.0 } }
      ]})");
}

std::string error_of(const json& doc) {
    return polyroll::test::input_error_of([&] { parse_observations(doc, "obs.json"); });
}

}  // namespace

TEST_CASE("observations: the bundled experiment.json reads and plans", "[observations]") {
    const ObservationFile f = read_observations("");
    REQUIRE(f.observations.size() >= 5);
    const ValidationPlan vp = make_validation_plan(f, 2, {});
    CHECK(vp.places.size() >= vp.plan.runs.size());
    CHECK(vp.plan.fields.back() == "run.seed");
}

TEST_CASE("observations: a good file is read and expanded, shared runs planned once", "[observations]") {
    const ObservationFile f = parse_observations(good_doc(), "obs.json");
    REQUIRE(f.observations.size() == 3);
    const Observation& band = f.observations[1];
    CHECK(band.angles_deg == std::vector<double>{10, 12, 14, 16});
    CHECK(band.scene["shell.preset"] == "octagon-small");
    CHECK(f.observations[0].scene["shell.preset"] == "hexagon-small");   // a section named by its preset
    CHECK(f.observations[0].scene["fill.material.preset"] == "bb");
    CHECK(band.linear_fit->slope_m_per_deg == 0.6);

    const ValidationPlan vp = make_validation_plan(f, 2, {{"fidelity.preset", "draft"}});
    // 1 point + 4 angles + 4 grid points, 2 seeds each; "rolls" is the grid's hexagon at 20 deg.
    CHECK(vp.places.size() == 18);
    CHECK(vp.plan.runs.size() == 16);
    std::set<std::size_t> runs_of_rolls;
    for (const RunPlace& p : vp.places)
        if (p.observation == 0) runs_of_rolls.insert(p.run);
    for (const RunPlace& p : vp.places)
        if (p.observation == 2 && p.label == "shell.preset=hexagon-small ramp.angle_deg=20") {
            CHECK(runs_of_rolls.count(p.run));
            CHECK(p.label_without_angle == "shell.preset=hexagon-small");  // the behaviour map's row
        }
    for (const PlannedRun& r : vp.plan.runs) CHECK(r.point["fidelity.preset"] == "draft");
    // The same file gives the same plan: what resuming relies on.
    CHECK(plan_to_json(make_validation_plan(f, 2, {{"fidelity.preset", "draft"}}).plan) == plan_to_json(vp.plan));
}

TEST_CASE("observations: bad files are refused with one line naming id, key, value and what is allowed",
          "[observations]") {
    struct Case {
        std::string pointer;  // JSON pointer to change
        json value;
        std::vector<std::string> words;
    };
    const std::vector<Case> cases = {
        {"/observations/0/tolerance/behaviour_share", 1.5, {"'rolls'", "tolerance.behaviour_share", "1.5", "at most 1"}},
        {"/observations/0/observed/behaviour", "rolled", {"'rolls'", "observed.behaviour", "rolled_to_end"}},
        {"/observations/0/scene/fill/ratio", 2.0, {"'rolls'", "fill.ratio", "2"}},
        {"/observations/0/scene/shell", "dodecagon", {"'rolls'", "dodecagon", "hexagon-small"}},
        {"/observations/0/scene/fill/colour", "red", {"'rolls'", "scene.fill.colour", "scene fields"}},
        {"/observations/0/tolerence", json::object(), {"'rolls'", "tolerence", "allowed: the keys"}},
        {"/observations/1/angles_deg", json{{"from", 12}, {"to", 14}, {"step", 1}}, {"'band'", "angles_deg", "11"}},
        {"/observations/1/scene/ramp", json{{"angle_deg", 12}}, {"'band'", "scene.ramp.angle_deg"}},
        {"/observations/1/angle_range_deg", json{15, 11}, {"'band'", "angle_range_deg", "from < to"}},
        {"/observations/1/tolerance", json{{"angle_range_deg", 1}}, {"'band'", "tolerance.slope_relative", "linear_fit"}},
        {"/observations/2/grid/ramp.angle_deg", json::array(), {"'grid'", "grid.ramp.angle_deg", "non-empty"}},
        {"/observations/2/grid/run.seed", json{1, 2}, {"'grid'", "grid.run.seed", "--seeds"}},
        {"/observations/2/id", "rolls", {"id", "each id once"}},
        {"/observations/2/observed/behaviour", "stopped", {"'grid'", "exactly one"}},
    };
    for (const Case& c : cases) {
        json doc = good_doc();
        doc[json::json_pointer(c.pointer)] = c.value;
        std::string msg = error_of(doc);
        if (msg.empty()) {
            // Values checked only when resolved (a scene field's range) fail when planned.
            try {
                make_validation_plan(parse_observations(doc, "obs.json"), 1, {});
            } catch (const polyroll::InputError& e) {
                msg = e.what();
            }
        }
        INFO(c.pointer << " -> " << msg);
        REQUIRE_FALSE(msg.empty());
        CHECK(msg.find('\n') == std::string::npos);
        CHECK(msg.rfind("obs.json", 0) == 0);
        for (const std::string& w : c.words) CHECK_THAT(msg, Catch::Contains(w));
    }
    CHECK_THAT(error_of(json::parse(R"({"observations": []})")), Catch::Contains("non-empty"));
    // A band without a line needs no slope tolerance.
    json no_line = good_doc();
    no_line["observations"][1]["observed"].erase("linear_fit");
    no_line["observations"][1]["tolerance"].erase("slope_relative");
    CHECK(error_of(no_line).empty());
    CHECK_THAT(error_of(json::parse(R"([1])")), Catch::Contains("an object"));
}

TEST_CASE("observations: a command-line field an observation sweeps is refused", "[observations]") {
    const ObservationFile f = parse_observations(good_doc(), "obs.json");
    CHECK_THROWS_AS(make_validation_plan(f, 1, {{"shell.preset", "decagon-small"}}), polyroll::InputError);
}

TEST_CASE("observations: named halves select their observations, and bad halves are refused", "[observations]") {
    json doc = good_doc();
    doc["halves"] = json{{"fit", json{"rolls", "grid"}}, {"held_back", json{"band"}}};
    const ObservationFile f = parse_observations(doc, "obs.json");
    REQUIRE(f.halves.size() == 2);
    const ObservationFile fit = half_of(f, "fit");
    REQUIRE(fit.observations.size() == 2);
    CHECK(fit.observations[0].id == "rolls");
    CHECK(fit.observations[1].id == "grid");
    // The folder's copy holds what was scored, and reads back: its halves name only the ids kept.
    CHECK(fit.doc["halves"] == json{{"fit", json{"rolls", "grid"}}});
    CHECK(parse_observations(fit.doc, "copy.json").observations.size() == 2);
    const ObservationFile one = only_observations(f, {"band"}, "--only");
    CHECK(one.doc["halves"] == json{{"held_back", json{"band"}}});
    CHECK(parse_observations(one.doc, "copy.json").halves.size() == 1);
    CHECK(half_of(f, "held_back").observations.front().id == "band");
    const std::string unknown = polyroll::test::input_error_of([&] { half_of(f, "test"); });
    CHECK_THAT(unknown, Catch::Contains("--half test") && Catch::Contains("fit, held_back"));
    const std::string none = polyroll::test::input_error_of([&] { half_of(parse_observations(good_doc(), "obs.json"), "fit"); });
    CHECK_THAT(none, Catch::Contains("names no halves"));

    json twice = doc;
    twice["halves"]["held_back"].push_back("rolls");
    CHECK_THAT(error_of(twice), Catch::Contains("halves.held_back") && Catch::Contains("one half at most"));
    json stranger = doc;
    stranger["halves"]["fit"].push_back("nobody");
    CHECK_THAT(error_of(stranger), Catch::Contains("\"nobody\"") && Catch::Contains("an id of this file"));
    json empty = doc;
    empty["halves"]["fit"] = json::array();
    CHECK_THAT(error_of(empty), Catch::Contains("halves.fit") && Catch::Contains("non-empty"));
}

TEST_CASE("observations: the bundled 3D reference reads, its halves cover it and plan", "[observations]") {
    const ObservationFile f = read_observations(POLYROLL_SOURCE_DIR "/assets/reference-3d.json");
    REQUIRE(f.halves.size() == 2);
    std::size_t in_halves = 0;
    for (const auto& [name, ids] : f.halves) in_halves += ids.size();
    CHECK(in_halves == f.observations.size());
    for (const Observation& ob : f.observations) {
        INFO(ob.id);
        CHECK(ob.source.find("dem3d") != std::string::npos);  // each entry names the runs that made it
        if (ob.angle_range_deg) CHECK(ob.angle_tolerance_deg == 0.5);
    }
    CHECK_FALSE(make_validation_plan(half_of(f, "fit"), 2, {}).plan.runs.empty());
}
