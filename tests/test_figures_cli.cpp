// polyroll figures on a run folder and a compare folder (speed and energy against time, each with
// its CSV), its refusals (a folder of no known kind, a bad --format, --runs without a sweep), and
// polyroll compare --json holding the same rows as the printed table.
#include <catch2/catch.hpp>

#include "test_helpers.h"

#include <filesystem>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

using namespace polyroll::test;  // read_file, have_matplotlib, run_command, kPolyrollExe
// A short scene at draft fidelity: fast and deterministic.
const std::string kScene = " --polygon octagon-small --fill 0.125 --angle 10 --fidelity draft --time-limit 1.5";

using polyroll::test::line_count;

// The start of compare's printed row for a model, as print_table lays it out.
std::string fmt_row(const std::string& model, const std::string& behaviour, double distance_m) {
    return fmt::format("{:<9} {:<24} {:>10.3f}", model, behaviour, distance_m);
}

}  // namespace

TEST_CASE("figures: a run folder and a compare folder give speed and energy against time, each with its CSV",
          "[figures][cli]") {
    const fs::path scratch = polyroll::test::scratch_dir("figures-cli-runs", true);
    REQUIRE(run_command(kPolyrollExe + " run" + kScene + " --out " + (scratch / "run").string()).exit_code == 0);
    REQUIRE(run_command(kPolyrollExe + " compare" + kScene + " --out " + (scratch / "cmp").string()).exit_code == 0);
    if (!have_matplotlib()) {
        WARN("no matplotlib for /usr/bin/python3: the figures are not drawn");
        return;
    }
    for (const char* folder : {"run", "cmp"}) {
        const fs::path out = scratch / (std::string("fig-") + folder);
        const auto r = run_command(kPolyrollExe + " figures " + (scratch / folder).string() + " --out " + out.string() +
                                   " --format png,svg");
        INFO(folder << ": " << r.out);
        REQUIRE(r.exit_code == 0);
        for (const char* stem : {"speed_vs_time", "energy_vs_time"})
            for (const char* ext : {".png", ".svg", ".csv"}) CHECK(fs::is_regular_file(out / (std::string(stem) + ext)));
        // The CSV holds every trajectory row of every run drawn, plus the impacts marked.
        const std::string energy = read_file(out / "energy_vs_time.csv");
        CHECK(energy.rfind("run,time_s,kinetic_J,potential_J,dissipated_J\n", 0) == 0);
        // A run of the default model is labelled with what auto ran (a filled shell: the grains).
        const std::string models = std::string(folder) == "run" ? "auto" : "grains segments rigid";
        const auto label = [&](const std::string& m) { return m == "auto" ? std::string("auto (grains)") : m; };
        std::istringstream names(models);
        size_t trajectory_rows = 0;
        for (std::string m; names >> m;) {
            const fs::path run_dir = std::string(folder) == "run" ? scratch / "run" : scratch / "cmp" / m;
            trajectory_rows += line_count(read_file(run_dir / "trajectory.csv")) - 1;
            CHECK(energy.find("\n" + label(m) + ",") != std::string::npos);
        }
        CHECK(line_count(energy) - 1 == trajectory_rows);
        // The short report: a row per run, each with the behaviour its summary.json states.
        const std::string report = read_file(out / "report.md");
        std::istringstream again(models);
        for (std::string m; again >> m;) {
            const fs::path run_dir = std::string(folder) == "run" ? scratch / "run" : scratch / "cmp" / m;
            const auto summary = nlohmann::json::parse(read_file(run_dir / "summary.json"));
            const std::string behaviour = summary["results"]["behaviour"];
            const std::map<std::string, std::string> words_of = {{"stopped", "rolls, then stops"},
                                                                 {"rolled_to_end", "rolls to the end"},
                                                                 {"stopped_at_first_impact", "stops at first impact"},
                                                                 {"time_limit", "time limit reached"}};
            REQUIRE(words_of.count(behaviour) == 1);
            const std::string words = words_of.at(behaviour);
            CHECK(report.find("| " + label(m) + " | " + words + " |") != std::string::npos);
        }
    }
}

TEST_CASE("figures: a folder of no known kind, a bad --format, --runs without a sweep: one line, exit 2, nothing "
          "written", "[figures][cli][bad-input]") {
    const fs::path scratch = polyroll::test::scratch_dir("figures-cli-bad", true);
    REQUIRE(run_command(kPolyrollExe + " run" + kScene + " --out " + (scratch / "run").string()).exit_code == 0);
    fs::create_directories(scratch / "empty");
    const fs::path out = scratch / "out";
    struct Case {
        std::string args;
        std::vector<std::string> words;
    };
    const std::vector<Case> cases = {
        {(scratch / "empty").string(), {"empty", "not a sweep, run or compare folder", "plan.json", "summary.json"}},
        {(scratch / "run").string() + " --format jpg", {"--format", "jpg", "png, svg or png,svg"}},
        {(scratch / "run").string() + " --format png,png", {"--format", "png,png"}},
        {(scratch / "run").string() + " --runs 0001", {"--runs", "0001", "only for a sweep folder"}},
    };
    // No matplotlib needed: the input is refused before the script is looked for.
    for (const Case& c : cases)
        polyroll::test::expect_refused("POLYROLL_PYTHON=/bin/false " + kPolyrollExe + " figures " + c.args + " --out " + out.string(),
                                       c.words, out);
}

TEST_CASE("compare --json: the table's rows as JSON, the same behaviours and numbers", "[compare][cli]") {
    const auto text = run_command(kPolyrollExe + " compare" + kScene);
    const auto json = run_command(kPolyrollExe + " compare" + kScene + " --json");
    REQUIRE(text.exit_code == 0);
    REQUIRE(json.exit_code == 0);
    const auto doc = nlohmann::json::parse(json.out);
    REQUIRE(doc["runs"].size() == 3);
    CHECK(doc["scene"]["ramp"]["angle_deg"] == 10.0);
    const std::vector<std::string> models = {"grains", "segments", "rigid"};
    for (size_t i = 0; i < models.size(); ++i) {
        const auto& row = doc["runs"][i];
        CHECK(row["model"] == models[i]);
        // The printed table's row for this model: "model behaviour distance_m ..." (distance rounded to mm).
        const std::string behaviour = row["behaviour"].get<std::string>();
        const std::string printed = fmt_row(models[i], behaviour, row["distance_m"].get<double>());
        INFO(text.out);
        CHECK(text.out.find(printed) != std::string::npos);
        CHECK(row["impacts"].get<int>() >= 0);
        CHECK(row.contains("terminal_velocity_m_s"));
    }
}

TEST_CASE("figures: a sweep matching the experiment's fig. 2A draws its line, rolls to the end at the ramp's end",
          "[figures][cli]") {
    const fs::path scratch = polyroll::test::scratch_dir("figures-cli-sweep", true);
    const fs::path sweep = scratch / "sweep", out = scratch / "fig";
    // The octagon of fig2a-octagon-third-behaviour (assets/experiment.json), rigid model: fast.
    REQUIRE(run_command(kPolyrollExe + " sweep --polygon octagon-small --fill 0.375 --material bb --ramp air-track "
                              "--angle 12,30 --model rigid --seeds 1 -q -j 1 --out " + sweep.string())
                .exit_code == 0);
    if (!have_matplotlib()) {
        WARN("no matplotlib for /usr/bin/python3: the figures are not drawn");
        return;
    }
    const auto r = run_command(kPolyrollExe + " figures " + sweep.string() + " --out " + out.string() + " --format svg");
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    for (const char* stem : {"distance_vs_angle", "behaviour_map"}) {
        CHECK(fs::is_regular_file(out / (std::string(stem) + ".svg")));
        CHECK(fs::is_regular_file(out / (std::string(stem) + ".csv")));
        CHECK(!fs::exists(out / (std::string(stem) + ".png")));  // --format svg: no PNG
    }
    CHECK(!fs::exists(out / ".figures-context.json"));  // the script's input, removed after
    const std::string d = read_file(out / "distance_vs_angle.csv");
    // The paper's line over its band (11 to 15.2 deg), and the ramp's end at the air track's length.
    CHECK(d.find(",paper_fit,11,") != std::string::npos);
    CHECK(d.find(",paper_fit,15.2,") != std::string::npos);
    CHECK(d.find(",ramp_end,,2.539,") != std::string::npos);
    // The 30 deg run rolls to the end and is drawn there.
    CHECK(d.find(",run,30,2.539,,,rolled_to_end,") != std::string::npos);
}
