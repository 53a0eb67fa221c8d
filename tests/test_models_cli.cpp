// polyroll compare and --model on the command line: every model writes the same files.
#include <catch2/catch.hpp>

#include "sim/model_registry.h"
#include "test_helpers.h"

#include <algorithm>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace {

using Output = polyroll::test::CommandResult;

using polyroll::test::run_polyroll;

const polyroll::test::Scratch fresh_dir("models-");

}  // namespace

TEST_CASE("polyroll run --model writes the same files for each model", "[models][cli]") {
    for (const char* model : {"rigid", "segments"}) {
        const auto dir = fresh_dir(model);
        const Output o = run_polyroll(std::string("run --model ") + model + " --fill 0.375 --angle 20 --out " + dir.string());
        INFO(o.out);
        REQUIRE(o.exit_code == 0);
        const auto summary = nlohmann::json::parse(polyroll::test::read_file(dir / "summary.json"));
        CHECK(summary["results"]["model"] == model);
        CHECK(summary["scene"]["run"]["model"] == model);
        CHECK(summary["results"]["model_valid"].is_boolean());
        CHECK(summary["results"].contains("model_invalid_time_s"));
        CHECK(polyroll::test::read_file(dir / "trajectory.csv").rfind("time_s,position_m,speed_m_s,angle_deg,", 0) == 0);
        CHECK(polyroll::test::read_file(dir / "impacts.csv").rfind("impact,time_s,position_m,kinetic_before_J,", 0) == 0);
        std::filesystem::remove_all(dir);
    }
}

TEST_CASE("polyroll run --model auto says what it chose, why, and when it handed over", "[models][cli]") {
    // An empty octagon at 30 deg lifts off: the rigid body goes on free of the ramp, no Box2D.
    const Output o = run_polyroll("run --model auto --fill 0 --sides 8 --angle 30");
    INFO(o.out);
    REQUIRE(o.exit_code == 0);
    CHECK(o.out.find("model              rigid, free to leave the ramp from t = ") != std::string::npos);
    CHECK(o.out.find("no hand-over to grains") != std::string::npos);
    CHECK(o.out.find("why                empty shell") != std::string::npos);
    const Output j = run_polyroll("run --model auto --fill 0 --sides 8 --angle 30 --json");
    REQUIRE(j.exit_code == 0);
    const auto summary = nlohmann::json::parse(j.out);
    CHECK(summary["scene"]["run"]["model"] == "auto");
    CHECK(summary["results"]["model_choice"]["model"] == "rigid");
    CHECK(summary["results"]["model_choice"]["then"] == "grains");
    CHECK(summary["results"]["model_choice"]["lift_off_time_s"].is_number());
    CHECK(summary["results"]["model_choice"]["hand_over_time_s"].is_null());
    CHECK(!summary.contains("engine"));
    // A triangle at 20 deg sets a face down flat: Box2D takes it from there, and the run says why.
    const Output t = run_polyroll("run --fill 0 --sides 3 --angle 20");
    INFO(t.out);
    REQUIRE(t.exit_code == 0);
    CHECK(t.out.find(", handed over to grains at t = ") != std::string::npos);
    CHECK(t.out.find("(a face set down on both its vertices at once)") != std::string::npos);
    // Misspelt: one clear line, exit 2.
    const Output bad = run_polyroll("run --model autoo");
    CHECK(bad.exit_code == 2);
    CHECK(std::count(bad.out.begin(), bad.out.end(), '\n') == 1);
    CHECK(bad.out.find("allowed: " + polyroll::model_list(polyroll::all_models()) + ", auto") != std::string::npos);
}

TEST_CASE("polyroll compare runs all three models and writes their runs and a speed CSV", "[models][cli]") {
    const auto dir = fresh_dir("compare");
    // An empty shell keeps the grain run to a single body: fast.
    const Output o = run_polyroll("compare --fill 0 --angle 20 --out " + dir.string());
    INFO(o.out);
    REQUIRE(o.exit_code == 0);
    for (const char* model : {"grains", "segments", "rigid"}) {
        CHECK(o.out.find(std::string("\n") + model + " ") != std::string::npos);
        CHECK(std::filesystem::exists(dir / model / "summary.json"));
        CHECK(std::filesystem::exists(dir / model / "trajectory.csv"));
        CHECK(std::filesystem::exists(dir / model / "impacts.csv"));
    }
    const std::string csv = polyroll::test::read_file(dir / "speed_vs_time.csv");
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

TEST_CASE("polyroll run --model dem3d: a missing Yade or a bad 3D field is one line and exit 2", "[models][cli][dem3d]") {
    const Output missing = polyroll::test::run_command("env POLYROLL_YADE=/nonexistent/yade " + std::string(POLYROLL_EXE) +
                                                       " run --model dem3d --angle 14");
    INFO(missing.out);
    CHECK(missing.exit_code == 2);
    CHECK(missing.out.find("POLYROLL_YADE=/nonexistent/yade: not an executable file") != std::string::npos);
    CHECK(std::count(missing.out.begin(), missing.out.end(), '\n') == 1);
    // No yade on the PATH: says how to install it.
    const Output none = polyroll::test::run_command("env PATH=/nonexistent " + std::string(POLYROLL_EXE) +
                                                    " run --model dem3d --angle 14");
    INFO(none.out);
    CHECK(none.exit_code == 2);
    CHECK(none.out.find("needs Yade, which is not installed: run third_party/setup.sh") != std::string::npos);
    CHECK(std::count(none.out.begin(), none.out.end(), '\n') == 1);
    for (const char* bad : {"--contact-time 5", "--time-step-share 0.9", "--channel-width 0.05"}) {
        const Output o = run_polyroll(std::string("run --model dem3d ") + bad);
        INFO(bad << ": " << o.out);
        CHECK(o.exit_code == 2);
        CHECK(o.out.find("dem3d.") != std::string::npos);
        CHECK(o.out.find("allowed") != std::string::npos);
    }
}

TEST_CASE("polyroll run --vertex-radius: out of its range or wider than half the wall, one line and exit 2",
          "[cli][vertex]") {
    // 0 to 5 mm, and at most half the wall (1 mm in the small shells' 2 mm walls).
    for (const char* bad : {"--vertex-radius -0.001", "--vertex-radius 0.006", "--vertex-radius 0.0015"}) {
        const Output o = run_polyroll(std::string("run --model grains ") + bad);
        INFO(bad << ": " << o.out);
        CHECK(o.exit_code == 2);
        CHECK(o.out.find("shell.vertex_radius_m") != std::string::npos);
        CHECK(o.out.find("allowed") != std::string::npos);
        CHECK(std::count(o.out.begin(), o.out.end(), '\n') == 1);
    }
}

TEST_CASE("polyroll run --model dem3d writes the usual files, the 3D engine and each impact's delayed energy",
          "[models][cli][dem3d]") {
    // The small hexagon a quarter full at 14 deg stops at its first impact: about 4 CPU-seconds in Yade.
    const auto dir = fresh_dir("dem3d");
    const Output o = run_polyroll("run --model dem3d --angle 14 --out " + dir.string());
    INFO(o.out);
    REQUIRE(o.exit_code == 0);
    CHECK(o.out.find("behaviour          stopped_at_first_impact") != std::string::npos);
    CHECK(o.out.find("grains             241") != std::string::npos);
    const auto summary = nlohmann::json::parse(polyroll::test::read_file(dir / "summary.json"));
    CHECK(summary["results"]["model"] == "dem3d");
    CHECK(summary["results"]["behaviour"] == "stopped_at_first_impact");
    CHECK(summary["results"]["grains"] == 241);
    // The step is shortened to fit a whole number in a tracker step: at most the share asked for.
    CHECK(summary["dem3d_engine"]["time_step_s"].get<double>() <= 0.001 * 0.0667);
    CHECK(summary["dem3d_engine"]["time_step_s"].get<double>() > 0.9 * 0.001 * 0.0667);
    CHECK(summary["dem3d_engine"]["yade_version"].get<std::string>().size() > 0);
    CHECK(!summary.contains("engine"));
    CHECK(summary["scene"]["dem3d"]["contact_time_s"] == 0.001);
    const std::string impacts = polyroll::test::read_file(dir / "impacts.csv");
    CHECK(impacts.rfind("impact,time_s,position_m,kinetic_before_J,kinetic_after_J,ratio,kinetic_3ms_after_J,ratio_3ms\n1,", 0) == 0);
    CHECK(impacts.find(",,\n") == std::string::npos);  // the delayed reading is there
    CHECK(!summary["dem3d_engine"].contains("channel"));  // held in its plane: nothing moves out of it
    CHECK(o.out.find("in the channel") == std::string::npos);
    std::filesystem::remove_all(dir);

    // In the experiment's channel the box is free in all six directions and its sides keep it in the
    // track: it moves less across than the clearance (7.9 cm channel, 6.4 cm box) and does not tip over.
    const auto in_channel = fresh_dir("dem3d-channel");
    const Output ch = run_polyroll("run --model dem3d --angle 14 --channel-width 0.079 --out " + in_channel.string());
    INFO(ch.out);
    REQUIRE(ch.exit_code == 0);
    CHECK(ch.out.find("  in the channel     moved ") != std::string::npos);
    const auto ch_summary = nlohmann::json::parse(polyroll::test::read_file(in_channel / "summary.json"));
    REQUIRE(ch_summary["dem3d_engine"].contains("channel"));
    const auto& motion = ch_summary["dem3d_engine"]["channel"];
    CHECK(motion["steps"].get<long>() > 100);
    CHECK(motion["steps_touching"].get<long>() <= motion["steps"].get<long>());
    CHECK(motion["max_offset_m"].get<double>() >= 0.0);
    CHECK(motion["max_offset_m"].get<double>() < 0.5 * (0.079 - 0.064) + 0.001);
    CHECK(motion["max_tilt_deg"].get<double>() < 10.0);
    CHECK(ch_summary["scene"]["dem3d"]["channel_width_m"] == 0.079);
    std::filesystem::remove_all(in_channel);

    // compare leaves it out unless asked, then runs it last, into dem3d/.
    const auto cmp = fresh_dir("dem3d-compare");
    const Output c = run_polyroll("compare --angle 14 --dem3d --out " + cmp.string());
    INFO(c.out);
    REQUIRE(c.exit_code == 0);
    CHECK(c.out.find("\ndem3d ") != std::string::npos);
    CHECK(std::filesystem::exists(cmp / "dem3d" / "summary.json"));
    CHECK(std::filesystem::exists(cmp / "rigid" / "summary.json"));
    std::filesystem::remove_all(cmp);
}
