// The polyroll command as a user runs it: bad input gives one line naming the value and what is
// allowed, exit code 2 and no output left behind; a good run writes its three files.
#include <catch2/catch.hpp>

#include "test_helpers.h"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>

#include <box2d/box2d.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

using Result = polyroll::test::CommandResult;

Result run_polyroll(const std::string& args) {
    return polyroll::test::run_command(std::string(POLYROLL_EXE) + " " + args);
}

fs::path scratch(const std::string& name) { return polyroll::test::scratch_dir("cli-" + name); }

size_t line_count(const std::string& s) {
    size_t lines = 0;
    for (char c : s) lines += c == '\n';
    return lines;
}

}  // namespace

TEST_CASE("bad flags: one line naming the value and the range, exit 2, nothing written", "[cli][bad-input]") {
    const fs::path out = scratch("bad-flags");
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
        {"--sides six", {"--sides", "six"}},
        {"--bogus 1", {"--bogus"}},
    };
    for (const Case& c : cases) {
        const Result r = run_polyroll("run " + c.args + " --out " + out.string());
        INFO("polyroll run " << c.args << " -> " << r.out);
        CHECK(r.exit_code == 2);
        CHECK(line_count(r.out) == 1);
        for (const auto& w : c.words) CHECK(r.out.find(w) != std::string::npos);
        CHECK(!fs::exists(out));
    }
}

TEST_CASE("bad scene files and output folders: exit 2, nothing written", "[cli][bad-input]") {
    const fs::path dir = scratch("bad-files");
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
        {"--scene " + (dir / "missing.json").string() + " --out " + out.string(), "cannot be read"},
        {"--scene " + dir.string() + " --out " + out.string(), "is a directory"},
        {"--out " + (dir / "a-file" / "out").string(), "cannot create the folder"},
        {"--out " + (dir / "a-file").string(), "not a folder"},
    };
    for (const Case& c : cases) {
        const Result r = run_polyroll("run " + c.args);
        INFO("polyroll run " << c.args << " -> " << r.out);
        CHECK(r.exit_code == 2);
        CHECK(line_count(r.out) == 1);
        CHECK(r.out.find(c.words) != std::string::npos);
        CHECK(!fs::exists(out));
    }
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

TEST_CASE("a run writes summary.json, trajectory.csv and impacts.csv", "[cli]") {
    const fs::path out = scratch("good-run");
    const Result r = run_polyroll("run --fill 0 --angle 10 --ramp wooden --out " + out.string());
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("rolled_to_end") != std::string::npos);
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
    CHECK(header == "time_s,position_m,speed_m_s,angle_deg,kinetic_J,potential_J,dissipated_J");
    std::ifstream imp(out / "impacts.csv");
    std::getline(imp, header);
    CHECK(header == "impact,time_s,position_m,kinetic_before_J,kinetic_after_J,ratio");
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
}

TEST_CASE("a diverged run exits with 3 and says why, its files complete", "[cli][divergence]") {
    const fs::path out = scratch("diverged");
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
    // The Box2D version as the library states it (b2_version), and CMake's project() version.
    const std::string box2d =
        "Box2D " + std::to_string(b2_version.major) + "." + std::to_string(b2_version.minor) + "." +
        std::to_string(b2_version.revision);
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
