// Scenes as JSON: presets, overrides, layering, the resolved form, and every kind of bad input.
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "sim/errors.h"
#include "sim/scene/scene_json.h"
#include "test_helpers.h"

using namespace polyroll;
using json = nlohmann::ordered_json;

TEST_CASE("a section preset sets its values, then the section's own keys override them", "[scene]") {
    const Scene s = test::scene_with(json::parse(R"({"shell": {"preset": "hexagon-large", "sides": 8},
        "fill": {"ratio": 0.5, "material": {"preset": "rice", "friction": 0.2}},
        "ramp": "wooden"})"));
    CHECK(s.shell.preset == "hexagon-large");
    CHECK(s.shell.sides == 8);
    CHECK(s.shell.mass_kg == 0.2428);
    CHECK(s.fill.ratio == 0.5);
    CHECK(s.fill.material.preset == "rice");
    CHECK(s.fill.material.friction == 0.2);
    CHECK(s.fill.material.bulk_density_kg_m3 == 800);
    CHECK(s.ramp.preset == "wooden");
    CHECK(s.ramp.length_m == 1.210);
    CHECK(s.ramp.angle_deg == 20.0);  // the angle is the scene's, kept when the ramp changes
}

TEST_CASE("later layers override earlier ones", "[scene]") {
    const Scene s = resolve_scene({SceneLayer{json::parse(R"({"ramp": {"angle_deg": 12}, "run": {"seed": 7}})"), "file", {}},
                                   SceneLayer{json::parse(R"({"ramp": {"angle_deg": 14}})"), "cli", {}}});
    CHECK(s.ramp.angle_deg == 14.0);
    CHECK(s.run.seed == 7);
}

TEST_CASE("the resolved scene round-trips through JSON", "[scene]") {
    const Scene s = test::scene_with(json::parse(R"({"shell": "octagon-small", "fill": {"ratio": 0.375, "material": "peas"},
        "ramp": {"angle_deg": 14.5}, "release": {"pose": "face"}, "fidelity": "precise", "run": {"seed": 99}})"));
    const json once = scene_to_json(s);
    const Scene again = test::scene_with(once);
    CHECK(scene_to_json(again) == once);
    CHECK(once.at("shell").at("lid_mass_fraction").is_null());
    CHECK(once.at("release").at("pose") == "face");
}

TEST_CASE("bad scene values are named with what is allowed", "[scene][bad-input]") {
    struct Case {
        const char* doc;
        std::vector<const char*> words;
    };
    const Case cases[] = {
        {R"({"shell": {"sides": 2}})", {"shell.sides = 2", "3 to 64"}},
        {R"({"shell": {"sides": 65}})", {"shell.sides = 65", "3 to 64"}},
        {R"({"shell": {"sides": 6.5}})", {"shell.sides", "whole number"}},
        {R"({"fill": {"ratio": -0.1}})", {"fill.ratio = -0.1", "0 to 1"}},
        {R"({"fill": {"ratio": 1.5}})", {"fill.ratio = 1.5", "0 to 1"}},
        {R"({"fill": {"ratio": "half"}})", {"fill.ratio", "must be a number"}},
        {R"({"ramp": {"angle_deg": -5}})", {"ramp.angle_deg = -5", "0 to 89"}},
        {R"({"ramp": {"angle_deg": 90}})", {"ramp.angle_deg = 90", "0 to 89"}},
        {R"({"fill": {"material": "gravel"}})", {"gravel", "bb, rice, peas"}},
        {R"({"shell": "dodecagon"})", {"dodecagon", "hexagon-small"}},
        {R"({"fidelity": "ultra"})", {"ultra", "standard"}},
        {R"({"shell": {"sidez": 6}})", {"unknown key 'shell.sidez'", "sides"}},
        {R"({"colour": "red"})", {"unknown key 'colour'"}},
        {R"({"release": {"pose": "edge"}})", {"release.pose", "vertex, face"}},
        {R"({"run": {"seed": -1}})", {"run.seed"}},
        {R"({"fill": {"ratio": 0.5, "material": {"diameter_m": 0.0001}}})", {"fill.material.diameter_m"}},
        {R"({"shell": {"wall_thickness_m": 0}})", {"shell.wall_thickness_m = 0"}},
        {R"({"run": {"sample_hz": 5000}})", {"run.sample_hz = 5000", "fidelity.step_hz"}},
        {R"({"run": {"model": "fluid"}})", {"run.model", "grains, segments, rigid"}},
    };
    for (const Case& c : cases) {
        const std::string msg = test::scene_error_of(c.doc);
        INFO("scene " << c.doc << " -> " << msg);
        REQUIRE(!msg.empty());
        CHECK(msg.find('\n') == std::string::npos);
        for (const char* w : c.words) CHECK(msg.find(w) != std::string::npos);
    }
}

TEST_CASE("too many grains are refused before anything is built", "[scene][bad-input]") {
    const std::string msg = test::scene_error_of(R"({"shell": "hexagon-large", "fill": {"ratio": 1, "material": {"preset": "rice", "diameter_m": 0.0006}}})");
    CHECK(msg.find("too many") != std::string::npos);
    CHECK(msg.find("20000") != std::string::npos);
}

TEST_CASE("scene files: malformed JSON, a directory, a missing file", "[scene][bad-input]") {
    namespace fs = std::filesystem;
    const fs::path dir = polyroll::test::scratch_dir("scene-files");
    fs::create_directories(dir);
    const fs::path bad = dir / "bad.json";
    std::ofstream(bad) << R"({"shell": {"sides": 6,}})";
    CHECK_THROWS_WITH(read_scene_file(bad), Catch::Contains("not valid JSON") && Catch::Contains("bad.json"));
    CHECK_THROWS_WITH(read_scene_file(dir), Catch::Contains("is a directory"));
    CHECK_THROWS_WITH(read_scene_file(dir / "missing.json"), Catch::Contains("cannot be read"));
    const fs::path arr = dir / "array.json";
    std::ofstream(arr) << "[1, 2]";
    CHECK_THROWS_WITH(read_scene_file(arr), Catch::Contains("JSON object"));
    fs::remove_all(dir);
}

TEST_CASE("a release tilt past one face's turn is refused", "[scene][bad-input]") {
    // A 64-gon turns 5.6 degrees per face; a 10 degree tilt would start its next vertex in the ramp.
    const std::string msg = test::scene_error_of(R"({"shell": {"sides": 64}, "release": {"tilt_deg": 10}})");
    CHECK(msg.find("release.tilt_deg = 10") != std::string::npos);
    CHECK(msg.find("n = 64") != std::string::npos);
    CHECK(test::scene_error_of(R"({"shell": {"sides": 6}, "release": {"tilt_deg": 10}})").empty());
}
