// polyroll validate as users run it: a tiny observations file run, scored and resumed; a malformed
// file and a folder holding another validation refused with one line and exit 2, nothing written.
#include <catch2/catch.hpp>

#include "test_helpers.h"

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

using polyroll::test::read_file;
using polyroll::test::have_matplotlib;
using polyroll::test::run_command;

using polyroll::test::kPolyrollExe;

// Two observations, six runs at draft fidelity over a short time: fast, and deterministic.
const char* kTinyObservations = R"({
  "observations": [
    { "id": "hexagon-20", "source": "test",
      "scene": { "shell": "hexagon-small", "fill": { "ratio": 0.25, "material": "bb" }, "ramp": { "preset": "air-track", "angle_deg": 20 } },
      "observed": { "behaviour": "rolled_to_end" },
      "tolerance": { "behaviour_share": 0.5 } },
    { "id": "octagon-band", "source": "test",
      "scene": { "shell": "octagon-small", "fill": { "ratio": 0.375, "material": "bb" }, "ramp": "air-track" },
      "angle_range_deg": [11, 15],
      "angles_deg": [10, 16],
      "observed": { "behaviour": "stopped", "linear_fit": { "slope_m_per_deg": 0.6, "intercept_m": -6.61 } },
      "tolerance": { "angle_range_deg": 1, "slope_relative": 0.3 } }
  ]})";

// Whether the figures can be drawn here (the Python polyroll validate picks, with matplotlib).
// A Python that cannot import matplotlib: polyroll validate says so and writes its scorecard; also
// spares the tests that are not about figures the time matplotlib takes to draw them.
const std::string kNoMatplotlib = "POLYROLL_PYTHON=/bin/false ";

fs::path write_observations(const fs::path& dir, const std::string& text) {
    fs::create_directories(dir);
    const fs::path p = dir / "obs.json";
    std::ofstream(p) << text;
    return p;
}

}  // namespace

TEST_CASE("validate: a tiny observations file is run, scored and resumed", "[validate][cli]") {
    const fs::path scratch = polyroll::test::scratch_dir("validate-cli", true);
    const fs::path obs = write_observations(scratch, kTinyObservations), out = scratch / "out";
    const std::string cmd = kPolyrollExe + " validate --observations " + obs.string() + " --seeds 2 --fidelity draft " +
                            "--time-limit 1.5 --jobs 2 -q --out " + out.string();
    const auto first = run_command(cmd);
    INFO(first.out);
    REQUIRE(first.exit_code == 0);
    CHECK_THAT(first.out, Catch::Contains("6 runs") && Catch::Contains("hexagon-20") && Catch::Contains("band start"));
    const std::string csv = read_file(out / "scorecard.csv");
    CHECK(csv.rfind("observation,check,experiment,simulation,agree,difference,unit,by\n", 0) == 0);
    CHECK(std::count(csv.begin(), csv.end(), '\n') == 5);  // header, one share check, three band checks
    const auto doc = nlohmann::json::parse(read_file(out / "scorecard.json"));
    CHECK(doc["format"] == "polyroll-scorecard-1");
    CHECK(doc["observations_total"] == 2);
    CHECK(doc["seeds"] == 2);
    CHECK(doc["overrides"]["fidelity.preset"] == "draft");
    CHECK(doc["observations"][1]["details"]["per_angle"].size() == 2);
    CHECK(doc["observations"][1]["runs"].size() == 4);  // what the figures draw, with results.csv
    if (have_matplotlib()) {
        // D against theta for the band, the behaviour map of both: PNG, SVG and CSV, each listed.
        for (const char* stem : {"d_vs_angle-octagon-band", "behaviour_map"})
            for (const char* ext : {".png", ".svg", ".csv"}) {
                const fs::path f = out / "figures" / (std::string(stem) + ext);
                CHECK(fs::file_size(f) > 0);
                CHECK_THAT(first.out, Catch::Contains("figure     " + f.string()));
            }
    }

    // The same command resumes: nothing left to run, the same scorecard; without matplotlib, one
    // line says what to install and the scorecard is written all the same.
    fs::remove(out / "scorecard.csv");
    const auto again = run_command(kNoMatplotlib + cmd);
    INFO(again.out);
    CHECK(again.exit_code == 0);
    CHECK_THAT(again.out, Catch::Contains("6 found done before"));
    CHECK_THAT(again.out, Catch::Contains("no figures drawn") && Catch::Contains("python3-matplotlib") &&
                              Catch::Contains("the scorecard is written"));
    CHECK(read_file(out / "scorecard.csv") == csv);
    if (have_matplotlib()) {
        // A figure script that fails is a fault (exit 1), said in one line; the scorecard stands.
        fs::create_directories(scratch / "broken");
        std::ofstream(scratch / "broken" / "polyroll_figures.py") << "import sys\nsys.exit(3)\n";
        fs::remove(out / "scorecard.csv");
        const auto broken = run_command("POLYROLL_FIGURES_DIR=" + (scratch / "broken").string() + " " + cmd);
        INFO(broken.out);
        CHECK(broken.exit_code == 1);
        CHECK_THAT(broken.out, Catch::Contains("the figure script failed (exit code 3); the scorecard is written"));
        CHECK(read_file(out / "scorecard.csv") == csv);
    }

    // Another command in the same folder is refused, unless --force starts over.
    const auto other = run_command(kNoMatplotlib + kPolyrollExe + " validate --observations " + obs.string() +
                                   " --seeds 1 --fidelity draft "
                                   "--time-limit 1.5 -q --out " + out.string());
    CHECK(other.exit_code == 2);
    CHECK_THAT(other.out, Catch::Contains("holds a different validation") && Catch::Contains("--out with a new folder"));
    CHECK(read_file(out / "scorecard.csv") == csv);

    // More seeds extend the folder: the six runs done are kept, three more run, all nine are scored.
    const auto more = run_command(kNoMatplotlib + kPolyrollExe + " validate --observations " + obs.string() +
                                  " --seeds 3 --fidelity draft --time-limit 1.5 --jobs 2 -q --out " + out.string());
    INFO(more.out);
    REQUIRE(more.exit_code == 0);
    CHECK_THAT(more.out, Catch::Contains("extends the validation in") && Catch::Contains("6 runs were planned there, 9 now"));
    CHECK_THAT(more.out, Catch::Contains("3 run now") && Catch::Contains("6 found done before"));
    const auto extended = nlohmann::json::parse(read_file(out / "scorecard.json"));
    CHECK(extended["seeds"] == 3);
    CHECK(extended["observations"][1]["runs"].size() == 6);
    fs::remove_all(scratch);
}

TEST_CASE("validate: shards run slices, the command without --shard scores them, and --force starts over",
          "[validate][cli]") {
    const fs::path scratch = polyroll::test::scratch_dir("validate-shards", true);
    const fs::path obs = write_observations(scratch, kTinyObservations), out = scratch / "out";
    const std::string cmd = kNoMatplotlib + kPolyrollExe + " validate --observations " + obs.string() +
                            " --seeds 2 --fidelity draft --time-limit 1.5 --jobs 1 -q --out " + out.string();
    for (const char* k : {"1/2", "2/2"}) {
        const auto r = run_command(cmd + " --shard " + k);
        INFO(r.out);
        REQUIRE(r.exit_code == 0);
        CHECK_THAT(r.out, Catch::Contains("without --shard to score"));
    }
    CHECK_FALSE(fs::exists(out / "scorecard.csv"));
    const auto all = run_command(cmd);
    INFO(all.out);
    REQUIRE(all.exit_code == 0);
    CHECK_THAT(all.out, Catch::Contains("0 run now") && Catch::Contains("6 found done before"));
    CHECK(fs::exists(out / "scorecard.csv"));
    CHECK(nlohmann::json::parse(read_file(out / "observations.json"))["observations"].size() == 2);

    const auto forced = run_command(kNoMatplotlib + kPolyrollExe + " validate --observations " + obs.string() +
                                    " --seeds 1 --fidelity draft "
                                    "--time-limit 1.5 -q --force --out " + out.string());
    INFO(forced.out);
    CHECK(forced.exit_code == 0);
    CHECK_THAT(forced.out, Catch::Contains("3 runs (1 seed each): 3 run now"));
    fs::remove_all(scratch);
}

TEST_CASE("validate: --only runs the observations named after printing the plan and its estimate",
          "[validate][cli]") {
    const fs::path scratch = polyroll::test::scratch_dir("validate-only", true);
    const fs::path obs = write_observations(scratch, kTinyObservations);
    const std::string cmd = kNoMatplotlib + kPolyrollExe + " validate --observations " + obs.string() +
                            " --seeds 2 --fidelity draft --time-limit 1.5 --jobs 2 -q";
    const auto one = run_command(cmd + " --only hexagon-20 --out " + (scratch / "one").string());
    INFO(one.out);
    REQUIRE(one.exit_code == 0);
    // The plan comes first: the observations, each one's runs, the seeds, and an upper bound on time.
    const auto plan = one.out.find("polyroll validate: 1 observation of " + obs.string() + ", 2 runs (2 seeds each)");
    const auto estimate = one.out.find("estimated at most");
    const auto ran = one.out.find("polyroll validate: 1 observation, 2 runs (2 seeds each): 2 run now");
    CHECK(plan != std::string::npos);
    CHECK_THAT(one.out, Catch::Contains("  hexagon-20      2 runs (1 scene x 2 seeds)"));
    CHECK(estimate != std::string::npos);
    CHECK(ran != std::string::npos);
    CHECK((plan < estimate && estimate < ran));
    const std::string csv = read_file(scratch / "one" / "scorecard.csv");
    CHECK_THAT(csv, Catch::Contains("hexagon-20") && !Catch::Contains("octagon-band"));
    // The folder's copy of the observations is what was scored.
    const auto copy = nlohmann::json::parse(read_file(scratch / "one" / "observations.json"));
    REQUIRE(copy["observations"].size() == 1);
    CHECK(copy["observations"][0]["id"] == "hexagon-20");

    // Repeated or listed, in any order: the file's order, and the whole file here.
    const auto both = run_command(cmd + " --only octagon-band --only hexagon-20 --out " + (scratch / "both").string());
    INFO(both.out);
    REQUIRE(both.exit_code == 0);
    CHECK_THAT(both.out, Catch::Contains("2 observations of") && Catch::Contains("6 runs (2 seeds each)") &&
                             Catch::Contains("  hexagon-20        2 runs (1 scene x 2 seeds)\n"
                                             "  octagon-band      4 runs (2 scenes x 2 seeds)\n"));
    const auto listed = run_command(cmd + " --only octagon-band,hexagon-20 --out " + (scratch / "both").string());
    INFO(listed.out);
    CHECK(listed.exit_code == 0);
    CHECK_THAT(listed.out, Catch::Contains("note: 6 of 6 runs found done before; 0 left") &&
                               Catch::Contains("6 found done before"));
    fs::remove_all(scratch);
}

TEST_CASE("validate: a malformed observation gives one line, exit 2, nothing written", "[validate][cli][bad-input]") {
    const fs::path scratch = polyroll::test::scratch_dir("validate-bad", true);
    std::string text = kTinyObservations;
    text.replace(text.find("\"behaviour_share\": 0.5"), 22, "\"behaviour_share\": 7");
    const fs::path obs = write_observations(scratch, text), out = scratch / "out";
    struct Case {
        std::string args;
        std::vector<std::string> words;
    };
    const std::vector<Case> cases = {
        {"--observations " + obs.string(), {"'hexagon-20'", "tolerance.behaviour_share", "7", "at most 1"}},
        {"--observations " + (scratch / "none.json").string(), {"cannot be read"}},
        {"--seed 3", {"--seed"}},
        {"--fidelity nonsense", {"nonsense", "draft"}},
        // The bundled file varies the angle itself: the value the user set is refused, not the file.
        {"--angle 12", {"ramp.angle_deg = 12 set on the command line", "'fig2a-octagon-third-behaviour'",
                        "its angles_deg", "--only picks"}},
        {"--angle 12 --only text-above-17-all-roll", {"ramp.angle_deg = 12", "grid [18,20]"}},
        {"--set fill.material.stickiness=1", {"stickiness", "not a scene field"}},
        {"--set fill.material.wall_friction=-1", {"wall_friction", "-1"}},
        // An id the file does not hold, alone or in a list, names the ids it does.
        {"--only nope", {"--only nope", "experiment.json", "allowed: fig7-hexagon-rolls, fig2a-octagon-third-behaviour"}},
        {"--only fig7-hexagon-rolls,fig7", {"--only fig7:", "allowed: fig7-hexagon-rolls"}},
    };
    for (const Case& c : cases)
        polyroll::test::expect_refused(kPolyrollExe + " validate " + c.args + " -q --out " + out.string(), c.words, out);
    fs::remove_all(scratch);
}

TEST_CASE("validate: an observation holding only a lab's terminal velocity is scored and drawn", "[validate][cli]") {
    // assets/experiment.json's format allows a measured number alone, with no behaviour; the figure
    // script raised KeyError: 'behaviour' after a right scorecard and drew nothing, exit 1.
    if (!have_matplotlib()) {
        WARN("no matplotlib for /usr/bin/python3: the figures are not drawn");
        return;
    }
    const fs::path scratch = polyroll::test::scratch_dir("validate-measured", true);
    const fs::path obs = write_observations(scratch, R"({
  "observations": [
    { "id": "my-lab-vt", "source": "my lab",
      "scene": { "shell": "hexagon-small", "fill": { "ratio": 0.25, "material": "bb" }, "ramp": { "preset": "air-track", "angle_deg": 20 } },
      "observed": { "terminal_velocity_m_s": 0.3 },
      "tolerance": { "terminal_velocity_m_s": 0.1 } }
  ]})"), out = scratch / "out";
    const auto r = run_command(kPolyrollExe + " validate --observations " + obs.string() +
                               " --seeds 2 --fidelity draft --time-limit 1.5 --jobs 2 -q --out " + out.string());
    INFO(r.out);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("terminal velocity") && !Catch::Contains("Traceback"));
    for (const char* ext : {".png", ".svg", ".csv"}) {
        const fs::path f = out / "figures" / (std::string("behaviour_map") + ext);
        CHECK(fs::exists(f));
        CHECK_THAT(r.out, Catch::Contains("figure     " + f.string()));
    }
    // The experiment's row says it saw numbers, not a behaviour.
    CHECK_THAT(read_file(out / "figures" / "behaviour_map.csv"), Catch::Contains("measured only"));
    fs::remove_all(scratch);
}
