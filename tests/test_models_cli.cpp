// polyroll compare and --model on the command line: every model writes the same files.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

#include <nlohmann/json.hpp>

namespace {

struct Output {
    int code = -1;
    std::string text;
};

Output run_polyroll(const std::string& args) {
    const std::string cmd = std::string(POLYROLL_EXE) + " " + args + " 2>&1";
    Output o;
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return o;
    std::array<char, 4096> buf{};
    size_t n = 0;
    while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) o.text.append(buf.data(), n);
    const int status = pclose(pipe);
    o.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return o;
}

std::string read_text(const std::filesystem::path& p) {
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

std::filesystem::path fresh_dir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("polyroll-test-models-" + name);
    std::filesystem::remove_all(dir);
    return dir;
}

}  // namespace

TEST_CASE("polyroll run --model writes the same files for each model", "[models][cli]") {
    for (const char* model : {"rigid", "segments"}) {
        const auto dir = fresh_dir(model);
        const Output o = run_polyroll(std::string("run --model ") + model + " --fill 0.375 --angle 20 --out " + dir.string());
        INFO(o.text);
        REQUIRE(o.code == 0);
        const auto summary = nlohmann::json::parse(read_text(dir / "summary.json"));
        CHECK(summary["results"]["model"] == model);
        CHECK(summary["scene"]["run"]["model"] == model);
        CHECK(summary["results"]["model_valid"].is_boolean());
        CHECK(summary["results"].contains("model_invalid_time_s"));
        CHECK(read_text(dir / "trajectory.csv").rfind("time_s,position_m,speed_m_s,angle_deg,", 0) == 0);
        CHECK(read_text(dir / "impacts.csv").rfind("impact,time_s,position_m,kinetic_before_J,", 0) == 0);
        std::filesystem::remove_all(dir);
    }
}

TEST_CASE("polyroll compare runs all three models and writes their runs and a speed CSV", "[models][cli]") {
    const auto dir = fresh_dir("compare");
    // An empty shell keeps the grain run to a single body: fast.
    const Output o = run_polyroll("compare --fill 0 --angle 20 --out " + dir.string());
    INFO(o.text);
    REQUIRE(o.code == 0);
    for (const char* model : {"grains", "segments", "rigid"}) {
        CHECK(o.text.find(std::string("\n") + model + " ") != std::string::npos);
        CHECK(std::filesystem::exists(dir / model / "summary.json"));
        CHECK(std::filesystem::exists(dir / model / "trajectory.csv"));
        CHECK(std::filesystem::exists(dir / model / "impacts.csv"));
    }
    const std::string csv = read_text(dir / "speed_vs_time.csv");
    CHECK(csv.rfind("time_s,grains_speed_m_s,segments_speed_m_s,rigid_speed_m_s\n", 0) == 0);
    // The models sample at the grain tracker's times, so the first rows have all three speeds.
    std::istringstream lines(csv);
    std::string header, first, second;
    std::getline(lines, header);
    std::getline(lines, first);
    std::getline(lines, second);
    CHECK(first == "0.000000,0.000000,0.000000,0.000000");
    CHECK(std::count(second.begin(), second.end(), ',') == 3);
    CHECK(second.find(",,") == std::string::npos);
    std::filesystem::remove_all(dir);
}
