// The polyroll command as a user runs it: bad input gives one line naming the value and what is
// allowed, exit code 2 and no output left behind; a good run writes its three files.
#include <catch2/catch.hpp>

#include "test_helpers.h"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

#include <box2d/box2d.h>
#include <nlohmann/json.hpp>

#include "sim/message_text.h"
#include "sim/scene/scene_json.h"
#include "sim/scene/shell_label.h"

namespace fs = std::filesystem;

namespace {

using Result = polyroll::test::CommandResult;

using polyroll::test::expect_refused;
using polyroll::test::kPolyrollExe;
using polyroll::test::line_count;
using polyroll::test::run_polyroll;

const polyroll::test::Scratch cli_scratch("cli-");

}  // namespace

TEST_CASE("bad flags: one line naming the value and the range, exit 2, nothing written", "[cli][bad-input]") {
    const fs::path out = cli_scratch("bad-flags");
    struct Case {
        std::string args;
        std::vector<std::string> words;
    };
    const std::vector<Case> cases = {
        {"--sides 2", {"shell.sides = 2", "--sides", "3 to 64"}},
        {"--sides 65", {"shell.sides = 65", "3 to 64"}},
        {"--fill -0.1", {"fill.ratio = -0.1", "--fill", "0 to 1"}},
        {"--fill 1.5", {"fill.ratio = 1.5", "0 to 1"}},
        {"--angle -5", {"ramp.angle_deg = -5", "--angle", "0 to 89"}},
        {"--angle 90", {"ramp.angle_deg = 90", "0 to 89"}},
        {"--material gravel", {"gravel", "bb, rice, peas"}},
        {"--polygon square", {"square", "hexagon-small"}},
        {"--fidelity ultra", {"ultra", "draft"}},
        {"--sides six", {"--sides six: not a whole number", "3 to 64", "see polyroll run --help"}},
        {"--fill abc", {"--fill abc: not a number", "0 to 1"}},
        {"--fill 0.5 --fill 0.6", {"--fill is given 2 times (allowed: once)"}},
        {"--sides 6 8", {"unexpected value '8'"}},
        {"--bogus 1", {"unknown flag '--bogus'", "see polyroll run --help"}},
        {"--fil 0.3", {"unknown flag '--fil'; did you mean '--fill'?"}},
    };
    for (const Case& c : cases) {
        const Result r = expect_refused(kPolyrollExe + " run " + c.args + " --out " + out.string(), c.words, out);
        // CLI11's own wording is replaced by the program's.
        for (const char* cli11 : {"Could not convert", "At Most", "required but received", "not expected"})
            CHECK(r.out.find(cli11) == std::string::npos);
    }
}

TEST_CASE("one vocabulary: --jobs 1 to 1024 everywhere, no --param alias, no --model for compare", "[cli][bad-input]") {
    // Each refused with one line and exit 2 before any run.
    const fs::path out = cli_scratch("vocabulary");
    struct Case {
        std::string args;
        std::vector<std::string> words;
    };
    const std::vector<Case> cases = {
        {"sweep --jobs 0 --out " + out.string(), {"--jobs 0 is out of range (allowed: 1 to 1024)"}},
        {"tradeoff --jobs 0 --out " + out.string(), {"--jobs 0 is out of range (allowed: 1 to 1024)"}},
        {"validate --jobs 0 --out " + out.string(), {"--jobs 0 is out of range (allowed: 1 to 1024)"}},
        {"calibrate --params ramp.friction --jobs 0 --out " + out.string(),
         {"--jobs 0 is out of range (allowed: 1 to 1024)"}},
        // calibrate's --param was --set's alias beside --params, and its errors named --set.
        {"calibrate --param ramp.friction --out " + out.string(), {"unknown flag '--param'; did you mean '--params'?"}},
        {"validate --param ramp.friction=0.5 --out " + out.string(), {"unknown flag '--param'"}},
        // compare runs every model: a --model flag would be listed and ignored.
        {"compare --model rigid --out " + out.string(), {"unknown flag '--model'", "see polyroll compare --help"}},
    };
    for (const Case& c : cases) expect_refused(kPolyrollExe + " " + c.args, c.words, out);
    const Result compare_help = run_polyroll("compare --help");
    CHECK(compare_help.out.find("--model") == std::string::npos);
    CHECK(compare_help.out.find("--sides") != std::string::npos);
    // sweep's --seed takes a list and --seeds a count: each one's help says which.
    const Result sweep_help = run_polyroll("sweep --help");
    CHECK(sweep_help.out.find("a LIST of seeds") != std::string::npos);
    CHECK(sweep_help.out.find("a COUNT: N seeds per point") != std::string::npos);
}

TEST_CASE("run prints lines a terminal shows whole and says what its terminal velocity averages", "[cli]") {
    // The auto model's "why" was one line of 250-600 characters: now a line or two, wrapped.
    for (const std::string args : {"--fill 0 --angle 30 --time-limit 3", "--time-limit 0.5"}) {
        const Result r = run_polyroll("run " + args);
        INFO("polyroll run " << args << " -> " << r.out);
        REQUIRE(r.exit_code == 0);
        std::istringstream lines(r.out);
        std::size_t why_lines = 0;
        bool in_why = false;
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("  why ", 0) == 0) in_why = true;
            else if (line.rfind("    ", 0) != 0) in_why = false;
            if (in_why) CHECK(line.size() <= 100);
            why_lines += in_why;
        }
        CHECK(why_lines >= 1);
        CHECK(why_lines <= 2);
    }
    // A shell that slides to the end has no face rhythm: its terminal velocity comes from the last
    // tenth of the run, said so, not "(mean over the last 0 faces)".
    const Result slide = run_polyroll("run --sides 3 --fill 1 --angle 85");
    INFO(slide.out);
    REQUIRE(slide.exit_code == 0);
    CHECK(slide.out.find("last 0 faces") == std::string::npos);
    CHECK(slide.out.find("m/s (mean speed over the last tenth of the run: fewer than two face impacts)") !=
          std::string::npos);
}

TEST_CASE("bench --auto refuses a --tilt one of its 16 shells cannot take before it runs any", "[cli][bad-input]") {
    // 25 deg fits the hexagon but not the octagon on the 5 degree ramp: the refusal comes before the
    // first row, so no table stops half-way.
    const Result r = run_polyroll("bench --auto --tilt 25 --no-render");
    INFO(r.out);
    CHECK(r.exit_code == 2);
    CHECK(line_count(r.out) == 1);
    for (const char* w : {"bench --auto", "release.tilt_deg = 25", "n = 8 at 5 degrees", "allowed: 0 to"})
        CHECK(r.out.find(w) != std::string::npos);
    CHECK(r.out.find("auto against grains") == std::string::npos);
}

TEST_CASE("a mistyped or missing command is named with the closest one, and polyroll help CMD is CMD --help",
          "[cli][bad-input]") {
    struct Case {
        std::string args;
        std::string words;
    };
    const std::vector<Case> cases = {
        {"rnu", "unknown command 'rnu'; did you mean 'run'?"},
        {"swep --fill 0.5", "unknown command 'swep'; did you mean 'sweep'?"},
        {"frobnicate", "unknown command 'frobnicate' (allowed: run, presets,"},
        {"--sides 6", "a command is required before '--sides'"},
        {"help rnu", "unknown command 'rnu'; did you mean 'run'?"},
    };
    for (const Case& c : cases) {
        const Result r = run_polyroll(c.args);
        INFO("polyroll " << c.args << " -> " << r.out);
        CHECK(r.exit_code == 2);
        CHECK(line_count(r.out) == 1);
        CHECK(r.out.find(c.words) != std::string::npos);
        CHECK(r.out.find("(see polyroll --help)") != std::string::npos);
        CHECK(r.out.find("subcommand") == std::string::npos);
    }
    const Result help = run_polyroll("help run");
    CHECK(help.exit_code == 0);
    CHECK(help.out == run_polyroll("run --help").out);
    CHECK(help.out.find("--sides INT") != std::string::npos);
    // Defaults shown in help: assets/defaults.json's angle and fill.
    CHECK(help.out.find("0 to 89 degrees (default: 20)") != std::string::npos);
    CHECK(help.out.find("from 0 to 1 (default: 0.25)") != std::string::npos);
    CHECK(run_polyroll("help").out == run_polyroll("--help").out);
    // Bare polyroll asks what the tool does: the help, exit 0, not a refusal.
    const Result bare = run_polyroll("");
    CHECK(bare.exit_code == 0);
    CHECK(bare.out == run_polyroll("--help").out);
    CHECK(bare.out.find("Subcommands:") != std::string::npos);
}

TEST_CASE("the real-time factor keeps significant digits for slow runs", "[cli]") {
    // A run at 0.4x real time printed "0x".
    CHECK(polyroll::real_time_text(1.0, 4.0) == "0.25x real time");
    CHECK(polyroll::real_time_text(1.0, 2.5) == "0.4x real time");
    CHECK(polyroll::real_time_text(1.0, 1000.0) == "0.001x real time");
    CHECK(polyroll::real_time_text(5.3, 1.0) == "5.3x real time");
    CHECK(polyroll::real_time_text(120.4, 1.0) == "120x real time");
    CHECK(polyroll::real_time_text(1.0, 0.0) == "too fast to time");
}

TEST_CASE("bad scene files and output folders: exit 2, nothing written", "[cli][bad-input]") {
    const fs::path dir = cli_scratch("bad-files");
    fs::create_directories(dir);
    std::ofstream(dir / "malformed.json") << "{\"fill\": {\"ratio\": 0.5,}";
    std::ofstream(dir / "unknown.json") << R"({"fill": {"ratio": 0.5, "colour": "red"}})";
    std::ofstream(dir / "a-file") << "x";
    const fs::path out = dir / "out";
    struct Case {
        std::string args;
        std::string words;
    };
    const std::vector<Case> cases = {
        {"--scene " + (dir / "malformed.json").string() + " --out " + out.string(), "not valid JSON"},
        {"--scene " + (dir / "unknown.json").string() + " --out " + out.string(), "unknown key 'fill.colour'"},
        {"--scene " + (dir / "missing.json").string() + " --out " + out.string(), "cannot be read: no such file"},
        {"--scene " + dir.string() + " --out " + out.string(), "is a directory"},
        {"--out " + (dir / "a-file" / "out").string(), "cannot create the folder"},
        {"--out " + (dir / "a-file").string(), "not a folder"},
    };
    for (const Case& c : cases) expect_refused(kPolyrollExe + " run " + c.args, {c.words}, out);
    // A non-empty folder is not overwritten without --force.
    fs::create_directories(out);
    std::ofstream(out / "keep.txt") << "mine";
    const Result r = run_polyroll("run --fill 0 --angle 10 --time-limit 0.2 --out " + out.string());
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("--force") != std::string::npos);
    CHECK(fs::exists(out / "keep.txt"));
    CHECK(!fs::exists(out / "summary.json"));
    fs::remove_all(dir);
}

// --set reaches any field of a scene file from run, render, compare and bench, as sweep, validate and
// calibrate have it: one value, over the scene file, beside the named flags but never against them.
TEST_CASE("run --set FIELD=VALUE sets any scene field, and a bad one is refused in one line", "[cli][bad-input]") {
    const fs::path out = cli_scratch("set-run");
    const Result r = run_polyroll("run --fill 0.25 --time-limit 0.2 --set fill.material.wall_friction=0.05 "
                                  "--set fill.material.grains_per_disc=null --set ramp.preset=wooden --out " +
                                  out.string());
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    std::ifstream in(out / "summary.json");
    const auto scene = nlohmann::json::parse(in).at("scene");
    CHECK(scene.at("fill").at("material").at("wall_friction") == 0.05);
    CHECK(scene.at("fill").at("material").at("grains_per_disc").is_null());
    CHECK(scene.at("ramp").at("preset") == "wooden");

    const fs::path refused = cli_scratch("set-refused");
    struct Case {
        std::string args;
        std::vector<std::string> words;
    };
    const std::vector<Case> cases = {
        {"run --set fill.material.wall_friction=0.05,0.1", {"--set fill.material.wall_friction=0.05,0.1", "one value"}},
        {"run --set fill.colour=1", {"'fill.colour' is not a scene field", "allowed:", "ramp.angle_deg"}},
        {"run --set ramp.angle_deg=12 --angle 10", {"--set ramp.angle_deg and --angle both set", "allowed: one"}},
        {"run --set fill.material.wall_friction=-1", {"fill.material.wall_friction = -1", "--set", "allowed: from 0"}},
        {"run --set ramp.angle_deg=12 --set ramp.angle_deg=13", {"--set ramp.angle_deg is given twice"}},
        {"run --set angle=12", {"'angle' is not a scene field"}},
        {"run --set =12", {"is not FIELD=VALUE"}},
        {"compare --set run.model=rigid", {"--set run.model: not allowed here"}},
    };
    for (const Case& c : cases) expect_refused(kPolyrollExe + " " + c.args + " --out " + refused.string(), c.words, refused);
}

TEST_CASE("a run writes summary.json, trajectory.csv and impacts.csv", "[cli]") {
    const fs::path out = cli_scratch("good-run");
    // A trailing slash, as shells complete folder names: the files line joins it as a path.
    const Result r = run_polyroll("run --fill 0 --angle 10 --ramp wooden --out " + out.string() + "/");
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("rolled_to_end") != std::string::npos);
    CHECK(r.out.find((out / "summary.json").string() + ", trajectory.csv") != std::string::npos);
    CHECK(r.out.find("//") == std::string::npos);
    std::ifstream in(out / "summary.json");
    const auto summary = nlohmann::json::parse(in);
    const auto& res = summary.at("results");
    for (const char* key : {"behaviour", "distance_m", "terminal_velocity_m_s", "impacts", "sim_time_s",
                            "wall_time_s", "grains", "grains_inside_at_end"})
        CHECK(res.contains(key));
    for (const char* key : {"mass_kg", "inertia_kg_m2", "pivot_radius_m"}) CHECK(summary.at("shell").contains(key));
    CHECK(summary.at("scene").at("ramp").at("preset") == "wooden");
    CHECK(summary.at("scene").at("fill").at("ratio") == 0.0);
    std::ifstream traj(out / "trajectory.csv");
    std::string header;
    std::getline(traj, header);
    CHECK(header == "time_s,position_m,speed_m_s,angle_deg,kinetic_J,potential_J,dissipated_J,fill_ahead_m,fill_up_m");
    std::ifstream imp(out / "impacts.csv");
    std::getline(imp, header);
    CHECK(header == "impact,time_s,position_m,kinetic_before_J,kinetic_after_J,ratio,kinetic_3ms_after_J,ratio_3ms");
    // Only the three files: no temporaries left behind.
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(out)) files += e.is_regular_file();
    CHECK(files == 3);

    // The summary's scene is itself a scene file that reproduces the run.
    std::ofstream(out.string() + "-scene.json") << summary.at("scene").dump();
    const Result again = run_polyroll("run --json --scene " + out.string() + "-scene.json");
    REQUIRE(again.exit_code == 0);
    const auto j = nlohmann::json::parse(again.out);
    CHECK(j.at("results").at("distance_m") == res.at("distance_m"));
    CHECK(j.at("results").at("impacts") == res.at("impacts"));
    fs::remove_all(out);
    fs::remove(out.string() + "-scene.json");
}

TEST_CASE("presets lists every bundled preset", "[cli]") {
    const Result r = run_polyroll("presets");
    REQUIRE(r.exit_code == 0);
    for (const char* name : {"hexagon-small", "octadecagon-small", "hexagon-large", "bb", "rice", "peas", "air-track",
                             "wooden", "draft", "standard", "precise", "reference"})
        CHECK(r.out.find(name) != std::string::npos);
    CHECK(r.out.find("fidelity levels (assets/fidelity.json):") != std::string::npos);
    CHECK(r.out.find("fidelitys") == std::string::npos);
    // Notes quote the experiment, not a "brief" the user never saw.
    CHECK(run_polyroll("presets --json").out.find("brief") == std::string::npos);
}

TEST_CASE("a diverged run exits with 3 and says why, its files complete", "[cli][divergence]") {
    const fs::path out = cli_scratch("diverged");
    const Result r = run_polyroll("run --step-hz 30 --angle 60 --out " + out.string());
    CHECK(r.exit_code == 3);
    CHECK(r.out.find("diverged") != std::string::npos);
    std::ifstream in(out / "summary.json");
    const auto summary = nlohmann::json::parse(in);
    CHECK(summary.at("results").at("behaviour") == "diverged");
    CHECK(summary.at("results").at("divergence").get<std::string>().find("finer fidelity") != std::string::npos);
    fs::remove_all(out);
}

// The name must not start with "--": ctest passes it to the Catch binary, which would read a flag.
TEST_CASE("polyroll --version and polyroll-sandbox --version name the version, the Box2D linked and the build type",
          "[cli][version]") {
    // Box2D's version as its package states it (2.4.1; the library's b2_version says 2.4.0), and
    // CMake's project() version.
    const std::string box2d = "Box2D " POLYROLL_TEST_BOX2D_VERSION ",";
    REQUIRE(std::string(POLYROLL_TEST_BOX2D_VERSION).rfind("2.4.", 0) == 0);
    for (const char* program : {POLYROLL_EXE, POLYROLL_SANDBOX_EXE}) {
        const Result r = polyroll::test::run_command(std::string(program) + " --version");
        INFO(program << " --version -> " << r.out);
        CHECK(r.exit_code == 0);
        CHECK(line_count(r.out) == 1);
        CHECK(r.out.find(" " POLYROLL_TEST_PROJECT_VERSION " ") != std::string::npos);
        CHECK(r.out.find(box2d) != std::string::npos);
        CHECK(r.out.find("build type " POLYROLL_TEST_BUILD_TYPE) != std::string::npos);
    }
    CHECK(run_polyroll("--version").out.rfind("polyroll 0", 0) == 0);
}

TEST_CASE("the shell is named for what it is: --sides 8 on the small hexagon is an octagon", "[cli]") {
    // The header and summary.json said "hexagon-small (n = 8)".
    const fs::path out = cli_scratch("octagon");
    const Result r = run_polyroll("run --sides 8 --fill 0 --time-limit 0.01 --out " + out.string());
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("polyroll run: octagon (n = 8) with hexagon-small's size, walls and mass,") != std::string::npos);
    CHECK(r.out.find("hexagon-small (n = 8)") == std::string::npos);
    std::ifstream in(out / "summary.json");
    const auto summary = nlohmann::json::parse(in);
    CHECK(summary.at("shell").at("label") == "octagon (n = 8) with hexagon-small's size, walls and mass");
    fs::remove_all(out);

    using namespace polyroll;
    auto label = [](const std::string& doc) { return shell_label(resolve_scene({parse_scene_text(doc, "t")})); };
    CHECK(label("{}") == "hexagon-small (n = 6)");
    CHECK(label(R"({"shell": "octagon-small"})") == "octagon-small (n = 8)");
    CHECK(label(R"({"shell": {"sides": 3}})") == "triangle (n = 3) with hexagon-small's size, walls and mass");
    CHECK(label(R"({"shell": {"preset": "hexagon-small", "sides": 8, "mass_kg": 0.05}})") ==
          "custom octagon (n = 8), from hexagon-small");
    CHECK(label(R"({"shell": {"preset": "octagon-small", "sides": 8}})") == "octagon-small (n = 8)");
    CHECK(polygon_name(18) == "octadecagon");
    CHECK(polygon_name(13) == "13-gon");
}
