// The window's presets on every surface but the window: the core reads them (names, lanes, errors),
// polyroll render --preset draws a race's lanes side by side and one lane with --lane, polyroll run
// --preset runs a lane with the numbers of the same scene given by flags, polyroll presets says which
// surface takes which, and bad names and lanes are refused naming the value and the allowed ones.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "render/colour.h"
#include "render/frame_encoder.h"
#include "render/png_writer.h"
#include "render/render_sequence.h"
#include "render/scene_view.h"
#include "sim/errors.h"
#include "sim/scene/scene_json.h"
#include "sim/scene/window_presets.h"
#include "test_helpers.h"

using namespace polyroll;
namespace fs = std::filesystem;

namespace {

const test::Scratch presets_scratch("window-presets-", true);

test::CommandResult cli(const std::string& args) { return test::run_polyroll(args); }

nlohmann::json summary_of(const fs::path& folder) {
    nlohmann::json j = nlohmann::json::parse(test::read_file(folder / "summary.json"));
    j["results"].erase("wall_time_s");  // the only field that depends on the clock
    return j;
}

// Whether some pixel of the image is within `tolerance` (sum over channels) of the colour.
bool has_colour(const render::DecodedPng& im, render::Rgba c, int tolerance = 12) {
    const int r = static_cast<int>(std::lround(c.r * 255)), g = static_cast<int>(std::lround(c.g * 255)),
              b = static_cast<int>(std::lround(c.b * 255));
    for (size_t i = 0; i + 2 < im.rgb.size(); i += 3)
        if (std::abs(im.rgb[i] - r) + std::abs(im.rgb[i + 1] - g) + std::abs(im.rgb[i + 2] - b) <= tolerance) return true;
    return false;
}

}  // namespace

TEST_CASE("the window's presets are read in the core: names, lanes, a lane as a layer, errors naming the value", "[presets]") {
    const std::vector<std::string> names = window_preset_names();
    REQUIRE(std::find(names.begin(), names.end(), "race") != names.end());
    const WindowPreset race = window_preset("race");
    CHECK(race.lanes.size() == 3);
    const std::vector<Scene> lanes = resolve_window_preset(race);
    REQUIRE(lanes.size() == 3);
    // A lane layer resolves to the same scene as the preset's lane.
    CHECK(scene_to_json(resolve_scene({window_preset_lane(race, 2)})) == scene_to_json(lanes[1]));
    const std::string unknown = test::input_error_of([] { window_preset("rcae"); });
    CHECK_THAT(unknown, Catch::StartsWith("--preset rcae: unknown window preset (allowed: default, "));
    CHECK_THAT(unknown, Catch::Contains("race"));
    CHECK_THAT(test::input_error_of([] { window_preset("rcae", "preset='rcae'"); }), Catch::StartsWith("preset='rcae': "));
    CHECK(test::input_error_of([&] { window_preset_lane(race, 4); }) == "--lane 4: the preset race has 3 lanes (allowed: 1 to 3)");
    CHECK(test::input_error_of([&] { window_preset_lane(race, 0, "lane=0"); }) == "lane=0: the preset race has 3 lanes (allowed: 1 to 3)");
    CHECK(test::input_error_of([] { window_preset_lane(window_preset("hexagon-bb"), 2); }) ==
          "--lane 2: the preset hexagon-bb has one lane (allowed: 1)");
}

TEST_CASE("polyroll render --preset of a race draws its lanes side by side, each lane's files as run --preset --lane", "[presets][render][cli]") {
    const fs::path base = presets_scratch("race");
    const std::string scene = "--time-limit 0.3";
    const auto render = cli("render --preset race " + scene + " --size 320x180 --fps 10 --hold 0.1 --out " +
                            (base / "frames").string());
    INFO(render.out);
    REQUIRE(render.exit_code == 0);
    CHECK_THAT(render.out, Catch::Contains("preset race, 3 lanes side by side"));
    // 0.3 s x 10 + 1 frames of the race, 1 held.
    CHECK(fs::exists(base / "frames" / render::frame_file_name(5)));
    CHECK_FALSE(fs::exists(base / "frames" / render::frame_file_name(6)));
    // Every lane in its colour (its badge and its row in the panel, its curve), on the held frame.
    const render::DecodedPng last = render::read_png(base / "frames" / render::frame_file_name(5));
    CHECK(last.width == 320);
    CHECK(last.height == 180);
    for (size_t i = 0; i < 3; ++i) {
        INFO("lane " << i + 1);
        CHECK(has_colour(last, render::lane_colour(i)));
    }
    CHECK_FALSE(has_colour(last, render::lane_colour(3)));  // no fourth lane
    for (int k = 1; k <= 3; ++k) {
        INFO("lane " << k);
        const fs::path run_dir = base / fmt::format("run-{}", k);
        const auto run = cli(fmt::format("run --preset race --lane {} {} --out {}", k, scene, run_dir.string()));
        REQUIRE(run.exit_code == 0);
        const fs::path lane_dir = base / "frames" / fmt::format("lane-{}", k);
        CHECK(summary_of(lane_dir) == summary_of(run_dir));
        CHECK(test::read_file(lane_dir / "trajectory.csv") == test::read_file(run_dir / "trajectory.csv"));
    }
}

TEST_CASE("polyroll render --preset --lane and a one-lane preset draw one lane, as render of the same scene", "[presets][render][cli]") {
    const fs::path base = presets_scratch("one");
    const std::string frames = " --time-limit 0.2 --size 320x180 --fps 10 --hold 0 --out ";
    REQUIRE(cli("render --preset race --lane 3" + frames + (base / "lane").string()).exit_code == 0);
    REQUIRE(cli("render --sides 6 --fill 1 --material bb --angle 17.5" + frames + (base / "flags").string()).exit_code == 0);
    CHECK_FALSE(fs::exists(base / "lane" / "lane-1"));  // one lane: its files beside the frames
    CHECK(summary_of(base / "lane")["results"] == summary_of(base / "flags")["results"]);
    CHECK(test::read_file(base / "lane" / render::frame_file_name(3)) == test::read_file(base / "flags" / render::frame_file_name(3)));
    const auto one = cli("render --preset stops-at-first-impact" + frames + (base / "preset").string());
    INFO(one.out);
    CHECK(one.exit_code == 0);
    CHECK(fs::exists(base / "preset" / "summary.json"));
}

TEST_CASE("polyroll run --preset runs the preset's lane, flags over it", "[presets][cli]") {
    const auto run = cli("run --preset race --lane 2 --angle 17 --time-limit 0.2 --json");
    INFO(run.out);
    REQUIRE(run.exit_code == 0);
    const nlohmann::ordered_json doc = nlohmann::ordered_json::parse(run.out);
    Scene expected = resolve_window_preset(window_preset("race"))[1];
    expected.ramp.angle_deg = 17;
    expected.run.time_limit_s = 0.2;
    CHECK(doc.at("scene") == scene_to_json(expected));
}

TEST_CASE("a bad --preset or --lane is refused naming the value and what is allowed, exit 2, nothing written", "[presets][cli][bad-input]") {
    const fs::path out = presets_scratch("bad") / "new";
    struct Case {
        std::string args;
        std::vector<std::string> words;
    };
    const std::vector<Case> cases = {
        {"render --preset rcae", {"--preset rcae: unknown window preset", "allowed: default,", "hexagon-large-rice", "race"}},
        {"render --preset race --lane 4", {"--lane 4: the preset race has 3 lanes (allowed: 1 to 3)"}},
        {"render --lane 2", {"--lane 2", "with --preset NAME"}},
        {"render --preset race --scene x.json", {"--scene x.json and --preset race", "one of them"}},
        {"run --preset race", {"--preset race: a race of 3 lanes", "--lane 1 to 3", "polyroll render --preset race"}},
        {"run --preset hexagon-bb --lane 2", {"--lane 2: the preset hexagon-bb has one lane (allowed: 1)"}},
    };
    for (const Case& c : cases)
        test::expect_refused(test::kPolyrollExe + " " + c.args + " --time-limit 0.1 --out " + out.string(), c.words, out);
}

TEST_CASE("polyroll presets lists the window's presets with a race's lanes and which surface takes which", "[presets][cli]") {
    const auto r = cli("presets");
    REQUIRE(r.exit_code == 0);
    for (const char* words : {"race (3 lanes)", "lane 2: hexagon-small, r = 0.4 bb, 17.5 deg on air-track",
                              "polyroll-sandbox --preset NAME", "polyroll render --preset NAME --out DIR",
                              "polyroll run --preset NAME [--lane K]", "polyroll.run(preset=NAME, lane=K)", "?preset=NAME"})
        CHECK_THAT(r.out, Catch::Contains(words));
}
