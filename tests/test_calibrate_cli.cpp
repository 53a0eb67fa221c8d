// polyroll calibrate as users run it: it finds again a value polyroll itself was run with (the
// recovery test), resumes from its folder, and refuses bad input with one line
// and exit 2, writing nothing.
#include <catch2/catch.hpp>

#include "test_helpers.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "sweep/results_table.h"

namespace fs = std::filesystem;

namespace {

using polyroll::test::read_file;
using polyroll::test::run_command;

using polyroll::test::kPolyrollExe;

// The small hexagon a quarter full of BBs rolls to the end of the wooden ramp at 25 degrees; at
// draft fidelity a run takes about 0.1 s. Its terminal velocity rises with the grains' restitution
// (measured over 4 seeds: 0.29 m/s at 0.3, 0.31 at 0.6, 0.34 at 0.7, 0.40 at 0.8, 0.52 at 0.9; the
// seed spread is about 0.01 m/s), so one measured number pins the restitution down.
// Column discs (21, grains_per_disc null): the calibrator is under test, and draft's step lets the finer
// default discs (124) leave the shell at 25 degrees on the wooden ramp. No closure: the numbers above
// were measured with the level at r.
const char* kSceneFlags = " --polygon hexagon-small --fill 0.25 --material bb --ramp wooden --angle 25 --fidelity draft"
                          " --set fill.material.grains_per_disc=null --closure none";

// The mean of one column of a results table (the sweep's own reader: sweep/results_table.h).
double column_mean(const fs::path& results_csv, const std::string& column) {
    const polyroll::sweep::TableFile t = polyroll::sweep::read_table(results_csv);
    REQUIRE(polyroll::sweep::find_column(t.header, column));
    REQUIRE_FALSE(t.rows.empty());
    double sum = 0.0;
    for (const auto& row : t.rows) sum += std::stod(polyroll::sweep::cell(t, row, column));
    return sum / static_cast<double>(t.rows.size());
}

// One column of a results table, by run id.
std::map<std::string, double> column_by_run(const fs::path& results_csv, const std::string& column) {
    const polyroll::sweep::TableFile t = polyroll::sweep::read_table(results_csv);
    REQUIRE(polyroll::sweep::find_column(t.header, column));
    std::map<std::string, double> out;
    for (const auto& row : t.rows)
        out[polyroll::sweep::cell(t, row, "run_id")] = std::stod(polyroll::sweep::cell(t, row, column));
    return out;
}

// One observation of the scene above: a lab's measured terminal velocity.
std::string lab_observations(double terminal_velocity_m_s, double tolerance_m_s) {
    nlohmann::ordered_json doc = {
        {"observations",
         {{{"id", "hexagon-terminal-velocity"},
           {"source", "polyroll itself"},
           {"scene",
            {{"shell", {{"preset", "hexagon-small"}}},
             // Column discs (21): the calibrator is under test here, and draft's step lets the
             // finer default discs (124) leave the shell at 25 degrees on the wooden ramp.
             {"fill", {{"ratio", 0.25}, {"material", {{"preset", "bb"}, {"grains_per_disc", nullptr}}}}},
             {"closure", {{"preset", "none"}}},
             {"ramp", {{"preset", "wooden"}, {"angle_deg", 25}}},
             {"fidelity", {{"preset", "draft"}}}}},
           {"observed", {{"terminal_velocity_m_s", terminal_velocity_m_s}}},
           {"tolerance", {{"terminal_velocity_m_s", tolerance_m_s}}}}}}};
    return doc.dump(2);
}

fs::path write_text(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p;
}

}  // namespace

TEST_CASE("calibrate: finds again the restitution polyroll was run with, within the seed noise, and resumes",
          "[calibrate][cli]") {
    const fs::path scratch = polyroll::test::scratch_dir("calibrate-recovery", true);
    // The "experiment": polyroll at a chosen restitution, over seeds the calibration does not use
    // (11-14), so the observation carries its own seed noise as a lab's would.
    constexpr double kTrueRestitution = 0.7;
    const auto truth = run_command(kPolyrollExe + " sweep" + kSceneFlags + " --set fill.material.restitution=0.7" +
                                   " --seed 11,12,13,14 --jobs 2 -q --out " + (scratch / "truth").string());
    INFO(truth.out);
    REQUIRE(truth.exit_code == 0);
    const double observed = column_mean(scratch / "truth" / "results.csv", "terminal_velocity_m_s");
    // Tolerance: about the standard error of a 4-seed mean (0.01 m/s / sqrt(4) = 0.005 m/s).
    const fs::path obs = write_text(scratch / "lab.json", lab_observations(observed, 0.006));
    const fs::path out = scratch / "out";
    // From the bb preset's own restitution (0.5, the scene's value) and a wide bound.
    const std::string cmd = kPolyrollExe + " calibrate --params fill.material.restitution=0.3:0.95 --observations " +
                            obs.string() + " --seeds 4 --max-evals 20 --jobs 2 --out " + out.string();
    const auto first = run_command(cmd);
    INFO(first.out);
    REQUIRE(first.exit_code == 0);
    CHECK_THAT(first.out, Catch::Contains("evaluation 0/20 (the scene's own values) fill.material.restitution=0.5"));
    const auto doc = nlohmann::json::parse(read_file(out / "calibration.json"));
    CHECK(doc["status"] == "done");
    CHECK(doc["params"][0]["start"] == 0.5);
    const double found = doc["params"][0]["best"].get<double>();
    // Within the seed noise: near 0.7 the terminal velocity rises about 0.45 m/s per unit of
    // restitution, and the two 4-seed means (observation and candidate) each carry about 0.005 m/s of
    // seed noise, so the restitution is known to about 0.016; 0.05 is three of those.
    CHECK(std::abs(found - kTrueRestitution) <= 0.05);
    CHECK(doc["objective_after"].get<double>() < 1.0);  // the mean within the tolerance
    CHECK(doc["objective_before"].get<double>() > 25.0);  // 0.5 is far off: 0.30 against 0.35 m/s
    CHECK(doc["checks_agreeing_after"] == 1);
    CHECK(doc["evaluations"].size() == 21);
    CHECK(doc["setup"]["observations"]["observations"][0]["id"] == "hexagon-terminal-velocity");
    CHECK(doc["command"].get<std::string>().find("--params fill.material.restitution=0.3:0.95") != std::string::npos);
    const std::string evaluations = read_file(out / "evaluations.csv");
    CHECK(evaluations.rfind("evaluation,fill.material.restitution,objective,", 0) == 0);

    // The calibrated scene file is a scene polyroll runs, with its provenance in its description.
    const auto scene = nlohmann::json::parse(read_file(out / "calibrated-scene.json"));
    CHECK(scene["fill"]["material"]["restitution"].get<double>() == found);
    CHECK_THAT(scene["description"].get<std::string>(), Catch::Contains("objective") && Catch::Contains("lab.json"));
    const auto rerun = run_command(kPolyrollExe + " run --scene " + (out / "calibrated-scene.json").string() +
                                   " --fidelity draft --time-limit 0.5");
    INFO(rerun.out);
    CHECK(rerun.exit_code == 0);

    // The same command resumes: every evaluation's runs are found done, and the result is the same.
    const auto again = run_command(cmd);
    INFO(again.out);
    REQUIRE(again.exit_code == 0);
    CHECK_THAT(again.out, Catch::Contains("found done"));
    CHECK_FALSE(Catch::Contains(" s); best").match(again.out));  // no evaluation ran anything
    CHECK(nlohmann::json::parse(read_file(out / "calibration.json"))["params"][0]["best"].get<double>() == found);
    const std::string resumed = read_file(out / "evaluations.csv");
    CHECK(std::count(resumed.begin(), resumed.end(), '\n') == 22);  // header and 21 evaluations

    // Another calibration in the same folder is refused, nothing changed.
    const auto other = run_command(kPolyrollExe + " calibrate --params fill.material.restitution=0.3:0.9 --observations " +
                                   obs.string() + " --seeds 4 --max-evals 0 -q --out " + out.string());
    CHECK(other.exit_code == 2);
    CHECK_THAT(other.out, Catch::Contains("holds another calibration"));
    CHECK(read_file(out / "evaluations.csv") == resumed);
    fs::remove_all(scratch);
}

TEST_CASE("calibrate: a first pass at one seed in coarser grains searches, and the final pass scores its best at "
          "every seed in the scene's grains", "[calibrate][cli]") {
    const fs::path scratch = polyroll::test::scratch_dir("calibrate-first-pass", true);
    const fs::path obs = write_text(scratch / "lab.json", lab_observations(0.35, 0.006)), out = scratch / "out";
    constexpr int kMaxEvals = 5;
    const std::string cmd = kPolyrollExe + " calibrate --params fill.material.restitution=0.3:0.95 --observations " +
                            obs.string() + " --seeds 2 --first-pass-seeds 1 --first-pass-grains 1.5 --max-evals " +
                            std::to_string(kMaxEvals) + " --jobs 2 --out " + out.string();
    const auto first = run_command(cmd);
    INFO(first.out);
    REQUIRE(first.exit_code == 0);
    CHECK_THAT(first.out, Catch::Contains("(1 seed, grains x1.5)") && Catch::Contains("(final pass, 2 seeds)"));
    const auto doc = nlohmann::json::parse(read_file(out / "calibration.json"));
    const auto& evals = doc["evaluations"];
    REQUIRE(evals.size() == kMaxEvals + 2);  // the start, the search's, the final pass
    // The start and the final pass at every seed in the scene's grains; the search at one seed, coarser.
    for (std::size_t i = 0; i < evals.size(); ++i) {
        const bool full = i == 0 || i + 1 == evals.size();
        INFO("evaluation " << i);
        CHECK(evals[i]["seeds"] == (full ? 2 : 1));
        CHECK(evals[i]["grain_scale"].get<double>() == (full ? 1.0 : 1.5));
        CHECK(evals[i]["runs"] == (full ? 2 : 1));
    }
    // The final pass scores the search's best: the lowest objective among the search's evaluations.
    std::size_t search_best = 1;
    for (std::size_t i = 1; i + 1 < evals.size(); ++i)
        if (evals[i]["objective"].get<double>() < evals[search_best]["objective"].get<double>()) search_best = i;
    CHECK(evals.back()["values"] == evals[search_best]["values"]);
    CHECK_THAT(doc["stop_reason"].get<std::string>(), Catch::Contains("first pass at 1 seed, grains x1.5"));
    // Kept only if it beats the start at every seed: never worse than the start.
    CHECK(doc["objective_after"].get<double>() <= doc["objective_before"].get<double>());
    const bool kept = evals.back()["objective"].get<double>() < evals[0]["objective"].get<double>();
    CHECK(doc["best_evaluation"] == (kept ? evals.size() - 1 : 0));

    // The search's runs have grains 1.5 times larger in diameter (these column discs are sized by the
    // grain's diameter), the same fill mass: fewer discs than every run in the scene's grains.
    const auto plan = nlohmann::json::parse(read_file(out / "plan.json"));
    const auto discs = column_by_run(out / "results.csv", "grains");
    int most_coarse = 0, fewest_fine = 1 << 30, coarse_runs = 0;
    for (const auto& r : plan["runs"]) {
        const int n = static_cast<int>(discs.at(r["id"].get<std::string>()));
        if (r["point"].contains("fill.material.diameter_m")) {
            ++coarse_runs;
            most_coarse = std::max(most_coarse, n);
        } else {
            fewest_fine = std::min(fewest_fine, n);
        }
    }
    CHECK(coarse_runs >= 2);  // the search's distinct candidates, one seed each
    CHECK(most_coarse < fewest_fine);

    // The same command resumes: everything found done, the same outcome.
    const auto again = run_command(cmd);
    INFO(again.out);
    REQUIRE(again.exit_code == 0);
    CHECK_FALSE(Catch::Contains(" s); best").match(again.out));
    CHECK(nlohmann::json::parse(read_file(out / "calibration.json"))["evaluations"] == evals);
    fs::remove_all(scratch);
}

TEST_CASE("calibrate: two shards side by side retrace the same path as one process", "[calibrate][cli]") {
    const fs::path scratch = polyroll::test::scratch_dir("calibrate-shards", true);
    const fs::path obs = write_text(scratch / "lab.json", lab_observations(0.35, 0.006));
    auto cmd = [&](const fs::path& out) {
        return kPolyrollExe + " calibrate --params fill.material.restitution=0.3:0.95 --observations " + obs.string() +
               " --seeds 2 --max-evals 6 --jobs 1 -q --out " + out.string();
    };
    const auto one = run_command(cmd(scratch / "one"));
    INFO(one.out);
    REQUIRE(one.exit_code == 0);
    // Two processes, one slice each of every candidate's runs, sharing the folder.
    const fs::path shared = scratch / "shared";
    const auto both = run_command("(" + cmd(shared) + " --shard 1/2 > " + (scratch / "a.log").string() + " 2>&1 & " +
                                  cmd(shared) + " --shard 2/2 > " + (scratch / "b.log").string() +
                                  " 2>&1; b=$?; wait $!; a=$?; exit $((a + b)))");
    INFO(read_file(scratch / "a.log") << read_file(scratch / "b.log"));
    REQUIRE(both.exit_code == 0);
    const auto solo = nlohmann::json::parse(read_file(scratch / "one" / "calibration.json"));
    const auto sharded = nlohmann::json::parse(read_file(shared / "calibration.json"));
    CHECK(sharded["params"] == solo["params"]);
    CHECK(sharded["evaluations"] == solo["evaluations"]);
    CHECK(fs::exists(shared / "shards" / "shard-1-of-2.csv"));
    CHECK(fs::exists(shared / "shards" / "shard-2-of-2.csv"));
    fs::remove_all(scratch);
}

TEST_CASE("calibrate: Ctrl-C exits 130 and the same command resumes", "[calibrate][cli]") {
    const fs::path scratch = polyroll::test::scratch_dir("calibrate-interrupt", true);
    const fs::path obs = write_text(scratch / "lab.json", lab_observations(0.35, 0.006)), out = scratch / "out";
    const std::string base = kPolyrollExe + " calibrate --params fill.material.restitution=0.3:0.95 --observations " +
                             obs.string() + " --seeds 6 --jobs 1 --out " + out.string();
    const std::string cmd = base + " --max-evals 30";
    // SIGINT once the first evaluation is written (30 evaluations of 6 runs take far longer).
    const auto stopped = run_command("sh -c '" + cmd + " & p=$!; while [ ! -s " + (out / "evaluations.csv").string() +
                                     " ]; do sleep 0.05; done; kill -INT $p; wait $p'");
    INFO(stopped.out);
    CHECK(stopped.exit_code == 130);
    CHECK_THAT(stopped.out, Catch::Contains("interrupted after"));  // stopped by the command, not killed
    CHECK(nlohmann::json::parse(read_file(out / "calibration.json"))["status"] == "running");
    const auto resumed = run_command(base + " --max-evals 2");  // a smaller budget: the same path, cut short
    INFO(resumed.out);
    // --max-evals is not part of the setup: the folder is resumed, not refused.
    REQUIRE(resumed.exit_code == 0);
    CHECK_THAT(resumed.out, Catch::Contains("evaluation 1/2") && Catch::Contains("found done"));
    fs::remove_all(scratch);
}

TEST_CASE("calibrate: the plan and its estimate come before the first evaluation, and --plan-only stops there",
          "[calibrate][cli]") {
    const fs::path scratch = polyroll::test::scratch_dir("calibrate-plan", true);
    const fs::path obs = write_text(scratch / "lab.json", lab_observations(0.35, 0.006));
    const fs::path out = scratch / "out";
    const std::string cmd = kPolyrollExe + " calibrate --params fill.material.restitution=0.3:0.95 --observations " +
                            obs.string() + " --seeds 3 --jobs 1 --out " + out.string();
    const auto plan = run_command(cmd + " --max-evals 4 --plan-only");
    INFO(plan.out);
    REQUIRE(plan.exit_code == 0);
    CHECK_THAT(plan.out, Catch::Contains("1 field against 1 observation") && Catch::Contains("3 seeds a scene"));
    CHECK_THAT(plan.out, Catch::Contains("fill.material.restitution") && Catch::Contains("from 0.3 to 0.95, start 0.5"));
    CHECK_THAT(plan.out, Catch::Contains("3 runs a candidate; 5 candidates at most"));
    CHECK_THAT(plan.out, Catch::Contains("estimated at most") && Catch::Contains("in all with 1 job"));
    CHECK_THAT(plan.out, !Catch::Contains("evaluation 0/"));
    CHECK_FALSE(fs::exists(out));  // nothing written
    // Without --plan-only the same lines come first, then the evaluations.
    const auto ran = run_command(cmd + " --max-evals 0");
    INFO(ran.out);
    REQUIRE(ran.exit_code == 0);
    const auto estimate = ran.out.find("estimated at most"), first = ran.out.find("evaluation 0/0");
    REQUIRE(estimate != std::string::npos);
    REQUIRE(first != std::string::npos);
    CHECK(estimate < first);
    fs::remove_all(scratch);
}

TEST_CASE("calibrate: bad input gives one line, exit 2, nothing written", "[calibrate][cli][bad-input]") {
    const fs::path scratch = polyroll::test::scratch_dir("calibrate-bad", true);
    const fs::path obs = write_text(scratch / "lab.json", lab_observations(0.35, 0.006)), out = scratch / "out";
    const std::string lab = " --observations " + obs.string();
    struct Case {
        std::string args;
        std::vector<std::string> words;
    };
    const std::vector<Case> cases = {
        {"--params fill.material.stickiness" + lab, {"stickiness", "not a scene field", "fill.material.restitution"}},
        {"--params shell.sides" + lab, {"shell.sides", "not a continuous number"}},
        {"--params fill.material.preset" + lab, {"fill.material.preset", "not a continuous number"}},
        {"--params run.seed" + lab, {"run.seed", "not a continuous number"}},
        {"--params fill.material.restitution=0.5:1.5" + lab, {"0.5:1.5", "outside the field's limits", "from 0", "1"}},
        {"--params ramp.friction=0.8:0.2" + lab, {"0.8:0.2", "FROM < TO"}},
        {"--params ramp.friction=low:high" + lab, {"low:high", "FROM:TO"}},
        {"--params ramp.friction,ramp.friction" + lab, {"ramp.friction", "twice"}},
        {"--params ramp.angle_deg" + lab, {"ramp.angle_deg", "hexagon-terminal-velocity", "sets it"}},
        {"--params ramp.friction --max-evals -1" + lab, {"--max-evals -1", "0 to 10000"}},
        {"--params ramp.friction --max-evals 20000" + lab, {"--max-evals 20000", "0 to 10000"}},
        {"--params ramp.friction --algorithm newton" + lab, {"newton", "sbplx"}},
        {"--params ramp.friction --start ramp.friction=2" + lab, {"ramp.friction=2", "outside the bounds", "0.3", "1.2"}},
        {"--params ramp.friction --start ramp.restitution=0.1" + lab, {"ramp.restitution", "not a field of --params"}},
        {"--params ramp.friction --set ramp.friction=0.5" + lab, {"ramp.friction", "not both"}},
        {"--params ramp.friction=0.1:0.5" + lab, {"the scene's ramp.friction=0.9", "outside the bounds"}},
        {"--params ramp.friction --seeds 0" + lab, {"--seeds"}},
        {"--params ramp.friction --seeds 2 --first-pass-seeds 2" + lab, {"--first-pass-seeds 2", "1 to --seeds - 1"}},
        {"--params ramp.friction --first-pass-grains 0.5" + lab, {"--first-pass-grains 0.5", "allowed 1", "to 3"}},
        {"--params ramp.friction --first-pass-grains 3.5" + lab, {"--first-pass-grains 3.5", "allowed 1", "to 3"}},
        {"--params ramp.friction --first-pass-grains nan" + lab, {"--first-pass-grains"}},
        {"--params ramp.friction --shard 3/2" + lab, {"3/2"}},
        {"--params ramp.friction --observations " + (scratch / "none.json").string(), {"cannot be read"}},
    };
    for (const Case& c : cases)
        polyroll::test::expect_refused(kPolyrollExe + " calibrate " + c.args + " -q --out " + out.string(), c.words, out);
    fs::remove_all(scratch);
}
