// The sandbox window end to end: under Xvfb (xvfb-run, from Debian's xvfb package) it runs a few
// hundred frames and saves a screenshot whose pixels show the panel's background where the panel
// is and the shell standing on the ramp; without a display it renders the default scene headless
// and says where the frames went; bad flags exit 2 with one line.
#include <catch2/catch.hpp>

#include "test_helpers.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/sandbox_settings.h"
#include "render/colour.h"
#include "render/png_writer.h"

namespace fs = std::filesystem;
using namespace polyroll;

namespace {

using Run = polyroll::test::CommandResult;

Run run(const std::string& cmd) { return polyroll::test::run_command(cmd); }

// This file's sandbox_scratch folders, created fresh: sandbox_scratch("smoke") is /tmp/polyroll-test-PID-sandbox-smoke/.
const polyroll::test::Scratch sandbox_scratch("sandbox-", true);

using polyroll::test::kSandboxExe;

struct Image {
    render::DecodedPng png;
    std::array<int, 3> at(int x, int y) const {
        const size_t i = (static_cast<size_t>(y) * static_cast<size_t>(png.width) + static_cast<size_t>(x)) * 3;
        return {png.rgb[i], png.rgb[i + 1], png.rgb[i + 2]};
    }
};

std::array<int, 3> rgb(render::Rgba c) {
    return {static_cast<int>(std::lround(c.r * 255)), static_cast<int>(std::lround(c.g * 255)),
            static_cast<int>(std::lround(c.b * 255))};
}

bool near(std::array<int, 3> a, std::array<int, 3> b, int tol) {
    for (int i = 0; i < 3; ++i)
        if (std::abs(a[i] - b[i]) > tol) return false;
    return true;
}

const std::string kXvfb = "xvfb-run -a -s \"-screen 0 1280x800x24\" ";

// The sandbox without a display, in `dir`, reading a default scene cut to `time_limit_s` simulated
// seconds from a replacement assets folder (POLYROLL_ASSETS, as a user's would be): a cheap fallback
// render. The flags follow.
std::string short_fallback_sandbox(const fs::path& dir, double time_limit_s) {
    const fs::path assets = dir / "short-default";
    fs::create_directories(assets);
    nlohmann::ordered_json defaults =
        nlohmann::ordered_json::parse(polyroll::test::read_file(fs::path(POLYROLL_SOURCE_DIR) / "assets" / "defaults.json"));
    defaults.at("scene").at("run").at("time_limit_s") = time_limit_s;
    std::ofstream(assets / "defaults.json") << defaults.dump(2) << "\n";
    return "cd " + dir.string() + " && env -u DISPLAY -u WAYLAND_DISPLAY POLYROLL_ASSETS=" + assets.string() + " " +
           kSandboxExe;
}

}  // namespace

// Under AddressSanitizer (tests/ci_checks.sh) the sandbox still runs with ASan and UBSan checking every
// access, but without the leak check at exit: Mesa's GLX driver, loaded with dlopen and unloaded by
// GLFW before exit, leaves allocations that LeakSanitizer can only attribute to an "<unknown module>",
// which no suppression can name. The leak checks of a run, a render and a sweep are in tests/ci_checks.sh.
std::string sandbox_env() {
    if (!polyroll::test::kSanitized) return "";
    const char* opts = std::getenv("ASAN_OPTIONS");
    return "ASAN_OPTIONS='" + std::string(opts ? opts : "") + ":detect_leaks=0' ";
}

TEST_CASE("the sandbox under Xvfb draws its panel and the shell on the ramp", "[app][sandbox]") {
    const Run which = run("command -v xvfb-run");
    INFO("xvfb-run is needed (Debian package xvfb, in third_party/debian-packages.txt)");
    REQUIRE(which.exit_code == 0);
    const fs::path dir = sandbox_scratch("smoke");
    const fs::path shot = dir / "shot.png";
    const Run r = run("cd " + dir.string() + " && " + sandbox_env() + kXvfb + kSandboxExe + " --screenshot " + shot.string() +
                      " --frames 300");
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    REQUIRE(fs::exists(shot));
    Image img{render::read_png(shot)};
    REQUIRE(img.png.width == app::kDefaultWidthPx);
    REQUIRE(img.png.height == app::kDefaultHeightPx);

    // The panel: its background colour fills much of the left column the panel occupies.
    const int panel_w = static_cast<int>(app::kPanelWidthPx);
    long panel_px = 0, total = 0;
    for (int y = 0; y < img.png.height; y += 2)
        for (int x = 0; x < panel_w; x += 2, ++total)
            if (img.at(x, y) == app::kPanelBackgroundRgb) ++panel_px;
    INFO("panel background share " << static_cast<double>(panel_px) / total);
    CHECK(panel_px > total / 4);
    // ... and not in the scene view, which has the renderer's background.
    CHECK(img.at(img.png.width - 20, 200) == rgb(render::palette::background));

    // The shell: its wall colour right of the panel, and the ramp directly under its lowest pixel.
    const auto wall = rgb(render::palette::shell_wall);
    int low_x = -1, low_y = -1;
    long wall_px = 0;
    for (int y = 0; y < img.png.height; ++y)
        for (int x = panel_w; x < img.png.width; ++x)
            if (near(img.at(x, y), wall, 2)) {
                ++wall_px;
                if (y > low_y) low_x = x, low_y = y;
            }
    INFO("shell wall pixels " << wall_px);
    REQUIRE(wall_px > 50);
    bool ramp_below = false;
    for (int y = low_y; y < std::min(img.png.height, low_y + 30); ++y) {
        const auto c = img.at(low_x, y);
        if (near(c, rgb(render::palette::ramp_surface), 40) || near(c, rgb(render::palette::ramp_body), 12)) ramp_below = true;
    }
    CHECK(ramp_below);
    fs::remove_all(dir);
}

// The window's own path, where each frame's physics runs on a second thread while the frame is
// drawn (a --frames capture steps first instead): --bench plays at real time through it.
TEST_CASE("the sandbox plays at real time with the physics beside the drawing", "[app][sandbox]") {
    const fs::path dir = sandbox_scratch("bench");
    const Run r = run("cd " + dir.string() + " && " + sandbox_env() + kXvfb + kSandboxExe +
                      " --bench --preset race --frames 90");
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("frames       90 in"));
    // The lanes moved: some simulated time passed, and tracker steps were taken on the physics thread.
    const auto at = r.out.find("tracker steps");
    REQUIRE(at != std::string::npos);
    const auto from = r.out.rfind("), ", at);
    REQUIRE(from != std::string::npos);
    CHECK(std::stol(r.out.substr(from + 3)) > 0);
    fs::remove_all(dir);
}

// On a software GL (llvmpipe under Xvfb) the window shows only what changed (the scene and the panels
// that moved) by copying parts of a back buffer it never swaps (platform.h, can_present_parts): the
// picture the back buffer holds after many frames of that must be the one a swapped, fully redrawn
// window holds, pixel for pixel (the panels kept from earlier frames, the status band and plots
// copied as they change), and the scene drawn only where its list changed (render/changed_regions.h).
// The race's four lanes move everywhere; the stops-abruptly octagon's pile comes to rest at 8.0 s,
// where a few grains still settle in small regions inside a still pile (a region's edge crossing a
// disc there once left a row of pixels blended twice: changed_regions.h, hold_whole_discs).
TEST_CASE("the window shown in parts holds the same picture as the window swapped whole", "[app][sandbox]") {
    const fs::path dir = sandbox_scratch("present");
    std::vector<std::string> benches;
    for (const std::string mode : {"parts", "swap"}) {
        const std::string env = mode == "swap" ? "POLYROLL_PRESENT=swap " : "";
        for (const std::string shot : {"race --frames 90", "stops-abruptly --frames 600"}) {
            const std::string name = shot.substr(0, shot.find(' '));
            const Run r = run("cd " + dir.string() + " && " + env + sandbox_env() + kXvfb + kSandboxExe + " --preset " +
                              shot + " --screenshot " + (dir / (mode + "-" + name + ".png")).string());
            INFO(r.out);
            REQUIRE(r.exit_code == 0);
        }
        const Run b = run("cd " + dir.string() + " && " + env + sandbox_env() + kXvfb + kSandboxExe +
                          " --bench --preset race --frames 5");
        INFO(b.out);
        REQUIRE(b.exit_code == 0);
        benches.push_back(b.out);
    }
    CHECK_THAT(benches[0], Catch::Contains("shown by     drawing and copying only what changed"));
    CHECK_THAT(benches[1], Catch::Contains("shown by     swapping the whole frame"));
    for (const std::string name : {"race", "stops-abruptly"}) {
        INFO(name);
        const render::DecodedPng parts = render::read_png(dir / ("parts-" + name + ".png")),
                                 swap = render::read_png(dir / ("swap-" + name + ".png"));
        REQUIRE(parts.width == swap.width);
        REQUIRE(parts.height == swap.height);
        CHECK(parts.rgb == swap.rgb);
    }
    fs::remove_all(dir);
}

// The large hexagon 0.8 full of rice (grains) costs more than the asset's measured machine steps at
// real time: the window steps it as asked all the same (same grains), says so, and offers the cheaper
// model; only --coarser (or the panel's button) steps that one. From a scene file (--scene).
TEST_CASE("the sandbox steps a costly scene as asked and a cheaper model only when picked", "[app][sandbox]") {
    const fs::path dir = sandbox_scratch("budget");
    std::ofstream(dir / "rice.json") << R"({"shell": "hexagon-large", "fill": {"ratio": 0.8, "material": "rice"},
                                           "run": {"model": "grains"}})";
    const std::string bench = "cd " + dir.string() + " && " + sandbox_env() + kXvfb + kSandboxExe +
                              " --bench --frames 5 --scene rice.json";
    const Run asked = run(bench);
    INFO(asked.out);
    REQUIRE(asked.exit_code == 0);
    CHECK_THAT(asked.out, Catch::Contains("scene file rice.json"));
    CHECK_THAT(asked.out, Catch::Contains("model        The scene as asked") &&
                              Catch::Contains("never differently") && Catch::Contains("Offered: grains"));
    CHECK_THAT(asked.out, Catch::Contains("fidelity standard"));
    const Run cheaper = run(bench + " --coarser 2x");
    INFO(cheaper.out);
    REQUIRE(cheaper.exit_code == 0);
    CHECK_THAT(cheaper.out, Catch::Contains("model        Stepping a cheaper model, as picked: grains 2x larger") &&
                                Catch::Contains("trade study"));
    // The grains stepped: fewer for the cheaper model than as asked.
    auto grains = [](const std::string& out) {
        const auto at = out.find(" grains, fidelity");
        REQUIRE(at != std::string::npos);
        return std::stol(out.substr(out.rfind(", ", at) + 2));
    };
    CHECK(grains(cheaper.out) < grains(asked.out) / 2);
    fs::remove_all(dir);
}

namespace {

using Box = std::array<double, 4>;  // x0, y0, x1, y1

Box box_of(const nlohmann::json& j) { return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>(), j.at(3).get<double>()}; }

bool overlap(const Box& a, const Box& b) { return a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]; }

bool inside(double x, double y, const Box& b) { return x >= b[0] && x <= b[2] && y >= b[1] && y <= b[3]; }

}  // namespace

// The window's layout at the sizes and UI scales a classroom uses: no panel's text runs past its
// box's right edge (the control panel and the readout table may scroll down, nothing sideways), the
// status band's text is whole inside it, the status covers no ramp's start and no lane badge, the
// ramps' starts and the badges are inside the scene, and the speed plot, where shown, is no thumbnail.
TEST_CASE("the sandbox's text fits its boxes and the status covers no ramp start at 800x600 to 1920x1080",
          "[app][sandbox]") {
    const fs::path dir = sandbox_scratch("layout");
    struct Case {
        std::string size;
        std::string scale;
        std::string extra;
    };
    for (const Case& c : {Case{"800x600", "1", "--preset race"}, Case{"800x600", "2", "--preset race --colour-by speed"},
                          Case{"1280x800", "1", "--preset race --colour-by speed"}, Case{"1280x800", "2", "--preset race"},
                          Case{"1920x1080", "1", "--preset race"}, Case{"1920x1080", "2", "--preset race"},
                          Case{"1280x800", "1", "--preset stops-abruptly --coarser 1.5x"}}) {
        INFO(c.size << " at UI scale " << c.scale << " " << c.extra);
        const fs::path report = dir / "layout.json";
        const Run r = run("cd " + dir.string() + " && " + sandbox_env() + "xvfb-run -a -s \"-screen 0 1920x1080x24\" " +
                          kSandboxExe + " " + c.extra + " --size " + c.size + " --ui-scale " + c.scale +
                          " --frames 20 --layout-report " + report.string());
        INFO(r.out);
        REQUIRE(r.exit_code == 0);
        const nlohmann::json j = nlohmann::json::parse(polyroll::test::read_file(report));
        const double font = j.at("font_px").get<double>();
        for (const auto& [name, window] : j.at("windows").items()) {
            INFO(name);
            const Box w = box_of(window), content = box_of(j.at("contents").at(name));
            CHECK(content[2] <= w[2] + 1.0);  // nothing cut at the right
            if (name == "status") CHECK(content[3] <= w[3] + 1.0);
        }
        const Box status = box_of(j.at("windows").at("status"));
        const Box scene = box_of(j.at("scene"));
        CHECK(scene[1] >= status[3] - 1.0);
        const auto& starts = j.at("ramp_starts");
        REQUIRE(!starts.empty());
        for (const auto& p : starts) {
            const double x = p.at(0).get<double>(), y = p.at(1).get<double>();
            CHECK_FALSE(inside(x, y, status));
            CHECK(inside(x, y, scene));
        }
        for (const auto& b : j.at("badges")) {
            CHECK_FALSE(overlap(box_of(b), status));
            CHECK(box_of(b)[1] >= scene[1] - 0.5);
            CHECK(box_of(b)[0] >= scene[0] - 0.5);
        }
        if (j.at("plots").contains("speed")) {
            const Box plot = box_of(j.at("plots").at("speed"));
            CHECK(plot[2] - plot[0] >= 12.0 * font);
            CHECK(plot[3] - plot[1] >= 6.0 * font);
        }
    }
    fs::remove_all(dir);
}

TEST_CASE("without a display the sandbox renders the default scene headless and says where", "[app][sandbox]") {
    const fs::path dir = sandbox_scratch("fallback");
    const Run r = run("cd " + dir.string() + " && env -u DISPLAY -u WAYLAND_DISPLAY " + kSandboxExe);
    INFO(r.out);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("no display") && Catch::Contains("headless"));
    CHECK_THAT(r.out, Catch::Contains("runs/default"));  // polyroll render's own lines name the folder
    CHECK(fs::exists(dir / "runs" / "default" / "frame_000001.png"));
    CHECK(fs::exists(dir / "runs" / "default" / "summary.json"));
    fs::remove_all(dir);
}

// --out names the headless render's folder too; run again, the fallback replaces its own earlier
// render (its marker says so) and never a folder it did not write, said on the first line. What is
// checked here is where the frames go, not the scene: its three renders read a default scene cut to
// 2 simulated seconds from a replacement assets folder (POLYROLL_ASSETS, as a user's would be),
// the test above renders the real one.
TEST_CASE("without a display the sandbox renders into --out and replaces only its own earlier render",
          "[app][sandbox]") {
    const fs::path dir = sandbox_scratch("fallback-out");
    const std::string sandbox = short_fallback_sandbox(dir, 2);
    const std::string cmd = sandbox + " --out mine/";
    const Run first = run(cmd);
    INFO(first.out);
    REQUIRE(first.exit_code == 0);
    CHECK_THAT(first.out, Catch::Contains("(polyroll render --out mine)"));
    REQUIRE(fs::exists(dir / "mine" / "frame_000001.png"));
    CHECK(fs::exists(dir / "mine" / "summary.json"));
    CHECK(fs::exists(dir / "mine" / ".polyroll-sandbox-fallback"));
    CHECK_FALSE(fs::exists(dir / "runs"));
    const auto files_before = std::distance(fs::directory_iterator(dir / "mine"), fs::directory_iterator());

    // Again: the same folder, its frames replaced, no mine-2.
    std::ofstream(dir / "mine" / "summary.json") << "old\n";
    const Run second = run(cmd);
    INFO(second.out);
    REQUIRE(second.exit_code == 0);
    CHECK_THAT(second.out, Catch::Contains("(polyroll render --out mine, replacing this fallback's earlier frames"));
    CHECK_FALSE(fs::exists(dir / "mine-2"));
    CHECK(polyroll::test::read_file(dir / "mine" / "summary.json") != "old\n");
    CHECK(std::distance(fs::directory_iterator(dir / "mine"), fs::directory_iterator()) == files_before);

    // A folder the fallback did not write is left as it is: the render goes to the next number.
    fs::create_directories(dir / "theirs");
    std::ofstream(dir / "theirs" / "notes.txt") << "kept\n";
    const Run third = run(sandbox + " --out theirs");
    INFO(third.out);
    REQUIRE(third.exit_code == 0);
    CHECK_THAT(third.out, Catch::Contains("(polyroll render --out theirs-2; theirs is not this fallback's and is "
                                          "left as it is)"));
    CHECK(fs::exists(dir / "theirs-2" / "frame_000001.png"));
    CHECK(polyroll::test::read_file(dir / "theirs" / "notes.txt") == "kept\n");
    CHECK(std::distance(fs::directory_iterator(dir / "theirs"), fs::directory_iterator()) == 1);
    fs::remove_all(dir);
}

// The scene the flags chose is the one rendered (a scene file cut to 1 simulated second, an empty
// shell, with --sides over it), written beside the frames so the render can be made again.
TEST_CASE("without a display the sandbox renders the scene its flags chose", "[app][sandbox]") {
    const fs::path dir = sandbox_scratch("fallback-chosen");
    std::ofstream(dir / "short.json") << R"({"fill": {"ratio": 0}, "run": {"time_limit_s": 1}})" << "\n";
    const Run r = run("cd " + dir.string() + " && env -u DISPLAY -u WAYLAND_DISPLAY " + kSandboxExe +
                      " --scene short.json --sides 5 --out shown");
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("rendering the chosen scene (scene file short.json as the flags changed it) "
                                      "headless instead (polyroll render --out shown --scene shown/sandbox-scene.json)"));
    CHECK(fs::exists(dir / "shown" / "frame_000001.png"));
    const auto summary = nlohmann::json::parse(polyroll::test::read_file(dir / "shown" / "summary.json"));
    CHECK(summary.at("scene").at("shell").at("sides") == 5);
    CHECK(summary.at("scene").at("fill").at("ratio") == 0);
    CHECK(summary.at("scene").at("run").at("time_limit_s") == 1);
    const auto written = nlohmann::json::parse(polyroll::test::read_file(dir / "shown" / "sandbox-scene.json"));
    CHECK(written.at("shell").at("sides") == 5);
    // The same folder without a chosen scene: the default scene's render, and no scene file left
    // naming frames it no longer drew (the default scene cut short by a replacement assets folder).
    const Run again = run(short_fallback_sandbox(dir, 1) + " --out shown");
    INFO(again.out);
    REQUIRE(again.exit_code == 0);
    CHECK_THAT(again.out, Catch::Contains("rendering the default scene (assets/defaults.json: the paper's Fig. 7 hexagon "
                                          "a quarter full of BBs at 20 deg) headless instead (polyroll render --out shown, "
                                          "replacing"));
    CHECK_FALSE(fs::exists(dir / "shown" / "sandbox-scene.json"));
    fs::remove_all(dir);
}

// Bad flags are refused before any window or headless render: run in a sandbox_scratch folder, nothing is
// written there (no runs/ of the headless fallback).
TEST_CASE("the sandbox refuses bad flags with one line and exit code 2", "[app][sandbox]") {
    using polyroll::test::expect_refused;
    const fs::path dir = sandbox_scratch("refused");
    const std::string sandbox = "cd " + dir.string() + " && env -u DISPLAY " + kSandboxExe + " ";
    const fs::path written = dir / "runs";
    struct Refused {
        std::string args, says;
    };
    for (const Refused& c : {Refused{"--preset nope", "allowed"}, Refused{"--frames -3", "allowed"},
                             Refused{"--ui-scale 9", "allowed"}, Refused{"--size 10x10", "allowed"},
                             Refused{"--screenshot x.png", "needs"},
                             // 0 frames would run forever: refused, not "unlimited".
                             Refused{"--frames 0", "allowed"}, Refused{"--theme light", "allowed"},
                             Refused{"--coarser 3x", "allowed"}})
        expect_refused(sandbox + c.args, {c.args + ":", c.says}, written);
    // A scene file that cannot be read: one line naming it, exit 2.
    CHECK(expect_refused(sandbox + "--scene no-such-file.json", {}, written).out ==
          "polyroll-sandbox: scene file no-such-file.json: cannot be read: no such file or directory\n");
    // What CLI11 itself refuses reads in the program's words too, naming the value and what is allowed,
    // as polyroll's flags do ("Could not convert: --ui-scale = abc" before).
    struct Case {
        std::string args, line;
    };
    for (const Case& c : {Case{"--ui-scale abc", "polyroll-sandbox: --ui-scale abc: not a number (allowed: 0.75 to 2.5) "
                                                 "(see polyroll-sandbox --help)\n"},
                          Case{"--frames many", "polyroll-sandbox: --frames many: not a whole number (allowed: 1 to "
                                                "10000000) (see polyroll-sandbox --help)\n"},
                          Case{"--theme", "polyroll-sandbox: --theme needs a value (allowed: projector, dark) (see "
                                          "polyroll-sandbox --help)\n"},
                          Case{"--ui-scal 2", "polyroll-sandbox: unknown flag '--ui-scal'; did you mean '--ui-scale'? "
                                              "(see polyroll-sandbox --help)\n"},
                          // The page's keys as flags: the page's checks, the flag named as typed.
                          Case{"--sides 99", "polyroll-sandbox: shell.sides = 99 (from --sides) is out of range (allowed: 3 to 64)\n"},
                          Case{"--fill abc", "polyroll-sandbox: --fill abc: not a number (allowed: from 0 to 1)\n"},
                          Case{"--seed -1", "polyroll-sandbox: --seed -1: not a whole number (allowed: 0 to 2^64-1)\n"}})
        CHECK(expect_refused(sandbox + c.args, {}, written).out == c.line);
    fs::remove_all(dir);
}
