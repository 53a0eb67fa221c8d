// The web page's scene from its address (app/page_settings.h): the keys a teacher's link uses,
// decoding, and every bad value refused with a message naming it and what is allowed.
#include <catch2/catch.hpp>

#include <string>

#include "app/page_settings.h"
#include "app/sandbox_state.h"
#include "sim/errors.h"

using namespace polyroll;
using namespace polyroll::app;

namespace {

// The message of the InputError parse_page_query throws ("" if it does not throw).
std::string refusal(const std::string& query) {
    try {
        parse_page_query(query);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("page address: preset and scene controls are read and applied to the selected lane", "[app][web]") {
    const PageSettings p = parse_page_query("?sides=8&fill=0.375&material=rice&angle=14");
    CHECK_FALSE(p.preset);
    REQUIRE(p.field("shell.sides"));
    CHECK(*p.field("shell.sides") == 8);
    CHECK(*p.field("fill.ratio") == 0.375);
    CHECK(*p.field("fill.material.preset") == "rice");
    CHECK(*p.field("ramp.angle_deg") == 14.0);
    CHECK_FALSE(p.frames);
    CHECK_FALSE(p.paused);
    CHECK_FALSE(p.bench);
    CHECK(parse_page_query("bench").bench);
    CHECK_FALSE(parse_page_query("bench=0").bench);

    SandboxState s = state_for_preset("default");
    apply_page_settings(p, s);
    const LaneControls& lane = s.lanes.at(0).controls;
    CHECK(lane.values.shell.sides == 8);
    CHECK(lane.values.fill.ratio == 0.375);
    CHECK(lane.values.fill.material.preset == "rice");
    CHECK(s.shared.values.ramp.angle_deg == 14.0);
    CHECK(s.playing);

    const PageSettings race = parse_page_query("preset=race&frames=240&paused");
    CHECK(*race.preset == "race");
    CHECK(*race.frames == 240);
    CHECK(race.paused);
    SandboxState r = state_for_preset("default");
    apply_page_settings(race, r);
    CHECK(r.preset == "race");
    CHECK(r.lanes.size() == state_for_preset("race").lanes.size());
    CHECK_FALSE(r.playing);
}

TEST_CASE("page address: empty, percent-encoded and '+' forms", "[app][web]") {
    const PageSettings none = parse_page_query("");
    CHECK_FALSE(none.preset);
    CHECK_FALSE(none.field("shell.sides"));
    CHECK(parse_page_query("?").frames == std::nullopt);
    CHECK(*parse_page_query("fill=0%2E5&&angle=%31%30").field("fill.ratio") == 0.5);
    CHECK(*parse_page_query("fill=0%2E5&&angle=%31%30").field("ramp.angle_deg") == 10.0);
    CHECK(*parse_page_query("preset=hexagon%2Drice").preset == "hexagon-rice");
}

TEST_CASE("page address: bad values are refused naming the value and what is allowed", "[app][web]") {
    // A value out of the field's range in the command line's words, named as Python names a keyword.
    CHECK(refusal("sides=2") == "shell.sides = 2 (from sides=2) is out of range (allowed: 3 to 64)");
    CHECK(refusal("sides=65") == "shell.sides = 65 (from sides=65) is out of range (allowed: 3 to 64)");
    CHECK(refusal("sides=6.5") == "sides=6.5: not a whole number (allowed: 3 to 64)");
    CHECK(refusal("sides=six") == "sides=six: not a whole number (allowed: 3 to 64)");
    CHECK(refusal("fill=1.5") == "fill.ratio = 1.5 (from fill=1.5) is out of range (allowed: from 0 to 1)");
    CHECK(refusal("fill=nan") == "fill=nan: not a number (allowed: from 0 to 1)");
    CHECK(refusal("angle=95").rfind("ramp.angle_deg = 95 (from angle=95) is out of range (allowed: ", 0) == 0);
    CHECK(refusal("seed=-1") == "seed=-1: not a whole number (allowed: 0 to 2^64-1)");
    CHECK(refusal("model=dem3d").rfind("run.model = dem3d (from model=dem3d) is not one the window runs (allowed: ",
                                       0) == 0);
    // A key without a value, or a value without a key, is said as such.
    CHECK(refusal("angle=").rfind("angle=: no value (allowed: ", 0) == 0);
    CHECK(refusal("sides") == "sides=: no value (allowed: 3 to 64)");
    CHECK(refusal("frames=") == "frames=: no value (allowed: 1 to 10000000)");
    CHECK(refusal("=5") == "=5: no setting name before the '=' (allowed: " + page_query_keys() + ")");
    CHECK(refusal("frames=0") == "frames=0: out of range (allowed: 1 to 10000000)");
    // Not a whole number is said as such, not as "out of range".
    CHECK(refusal("frames=1.5") == "frames=1.5: not a whole number (allowed: 1 to 10000000)");
    CHECK(refusal("frames=abc") == "frames=abc: not a whole number (allowed: 1 to 10000000)");
    CHECK(refusal("frames=99999999") == "frames=99999999: out of range (allowed: 1 to 10000000)");
    CHECK(refusal("paused=yes") == "paused=yes: unknown (allowed: 1, 0, or no value)");
    const std::string preset = refusal("preset=nonagon");
    CHECK(preset.rfind("preset=nonagon: unknown (allowed: default, ", 0) == 0);
    CHECK(preset.find("race") != std::string::npos);
    const std::string material = refusal("material=sand");
    CHECK(material.rfind("material=sand: unknown material preset 'sand' (allowed: ", 0) == 0);
    CHECK(material.find("rice") != std::string::npos);
    CHECK(refusal("colour=red") == "colour: unknown setting in the address (allowed: " + page_query_keys() + ")");
    CHECK(page_query_keys().rfind("preset, polygon, sides, fill, material, ramp, angle, ", 0) == 0);
    // A key given twice is refused naming it, whichever value came second (the page would show one of them).
    CHECK(refusal("fill=0.5&fill=0.3") == "fill=0.3: fill is given twice in the address (allowed: each setting once)");
    CHECK(refusal("paused&sides=6&paused=0") ==
          "paused=0: paused is given twice in the address (allowed: each setting once)");
    // Every bad setting is named, in the address's order, the good ones between them not.
    CHECK(refusal("sides=2&fill=0.5&angle=95&colour=red") ==
          refusal("sides=2") + "; " + refusal("angle=95") + "; " + refusal("colour=red"));
    CHECK(refusal("fill=2&fill=3") == refusal("fill=2") + "; fill=3: fill is given twice in the address (allowed: "
                                                          "each setting once)");
    // Every refusal names its value; a good query is not refused.
    CHECK(refusal("preset=race&sides=8").empty());
}

// polyroll-sandbox's flags of the page's names go through the page's checks, the flag named as the
// command line names it.
TEST_CASE("window flags: the page's keys with the page's checks and the flag's own name", "[app][web]") {
    const PageSettings p = parse_window_flags({{"sides", "8"}, {"fill", "0.375"}, {"material", "rice"},
                                               {"angle", "14"}, {"seed", "3"}});
    CHECK(*p.field("shell.sides") == 8);
    CHECK(*p.field("fill.ratio") == 0.375);
    CHECK(*p.field("fill.material.preset") == "rice");
    CHECK(*p.field("ramp.angle_deg") == 14.0);
    CHECK(*p.field("run.seed") == 3);
    SandboxState s = state_for_preset("default");
    apply_page_settings(p, s);
    const Scene scene = scenes_for(s).front();
    CHECK(scene.shell.sides == 8);
    CHECK(scene.run.seed == 3);
    CHECK_THROWS_WITH(parse_window_flags({{"sides", "99"}}),
                      "shell.sides = 99 (from --sides) is out of range (allowed: 3 to 64)");
    CHECK_THROWS_WITH(parse_window_flags({{"material", "sand"}}),
                      Catch::StartsWith("--material: unknown material preset 'sand' (allowed: "));
    CHECK_THROWS_WITH(parse_window_flags({{"seed", "1e3"}}), Catch::StartsWith("--seed 1e3: not a whole number"));
    // A value holding the address's own separators is one value, not more of the address.
    CHECK_THROWS_WITH(parse_window_flags({{"fill", "0.5&sides=9"}}), Catch::StartsWith("--fill 0.5&sides=9: not a number"));
}
