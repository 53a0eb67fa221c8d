// polyroll sweep as users run it: a plan split into slices under GNU parallel (two local jobs) and
// merged gives the one-process table; bad grid flags and folders fail with one line and exit 2.
#include <catch2/catch.hpp>

#include "test_helpers.h"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <sstream>
#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include "sweep/sweep_plan.h"

namespace fs = std::filesystem;

namespace {

using Result = polyroll::test::CommandResult;

Result shell(const std::string& cmd) { return polyroll::test::run_command(cmd); }

using polyroll::test::kPolyrollExe;

const polyroll::test::Scratch sweep_cli_scratch("sweep-cli-");

using polyroll::test::read_file;
using polyroll::test::table_without_wall_time;

// A small grid: empty and lightly filled shells, two materials, three angles, two seeds. (An invalid
// point is refused before the sweep starts; failed rows are test_sweep.cpp's.)
const std::string kGrid =
    "--sides 6,8 --fill 0,0.125 --material bb,rice --angle 10,25,40 --seeds 2 --fidelity draft --ramp wooden "
    "--time-limit 0.8 -q";

}  // namespace

TEST_CASE("a plan run as slices under GNU parallel and merged equals the one-process table", "[sweep][cli]") {
    REQUIRE(shell("parallel --version").exit_code == 0);  // GNU parallel: third_party/debian-packages.txt
    const fs::path one = sweep_cli_scratch("one"), big = sweep_cli_scratch("big");
    const Result single = shell(kPolyrollExe + " sweep " + kGrid + " --jobs 1 --out " + one.string());
    INFO(single.out);
    REQUIRE(single.exit_code == 0);

    const Result plan = shell(kPolyrollExe + " sweep " + kGrid + " --out " + big.string() + " --plan-only");
    INFO(plan.out);
    REQUIRE(plan.exit_code == 0);
    CHECK(fs::exists(big / "plan.json"));
    CHECK_FALSE(fs::exists(big / "results.csv"));
    CHECK(read_file(big / "plan.json") == read_file(one / "plan.json"));

    const Result slices = shell("parallel --will-cite --halt now,fail=1 -j2 " + kPolyrollExe + " sweep --from " + big.string() +
                                " --shard {}/4 --jobs 1 -q ::: 1 2 3 4");
    INFO(slices.out);
    REQUIRE(slices.exit_code == 0);
    const Result merged = shell(kPolyrollExe + " sweep --merge " + big.string());
    INFO(merged.out);
    REQUIRE(merged.exit_code == 0);
    CHECK_THAT(merged.out, Catch::Contains("5 tables") && Catch::Contains("48 of 48 runs"));
    const std::string a = read_file(one / "results.csv"), b = read_file(big / "results.csv");
    CHECK(std::count(a.begin(), a.end(), '\n') == 49);
    CHECK(table_without_wall_time(a) == table_without_wall_time(b));
    // Each run's summary is there too, under its id.
    CHECK(std::distance(fs::directory_iterator(big / "runs"), fs::directory_iterator{}) ==
          std::distance(fs::directory_iterator(one / "runs"), fs::directory_iterator{}));

    // The same command again resumes: nothing left to run, the table unchanged.
    const Result again = shell(kPolyrollExe + " sweep " + kGrid + " --jobs 2 --out " + one.string());
    INFO(again.out);
    CHECK(again.exit_code == 0);
    CHECK_THAT(again.out, Catch::Contains("48 found done before"));
    CHECK(table_without_wall_time(read_file(one / "results.csv")) == table_without_wall_time(a));
    fs::remove_all(one);
    fs::remove_all(big);
}

TEST_CASE("sweep: bad grid flags and folders give one line, exit 2, nothing written", "[sweep][cli][bad-input]") {
    const fs::path out = sweep_cli_scratch("bad");
    struct Case {
        std::string args;
        std::vector<std::string> words;
    };
    const std::vector<Case> cases = {
        {"--fill 0:1:0 --out " + out.string(), {"--fill", "step 0"}},
        {"--angle 30:5:1 --out " + out.string(), {"--angle", "backwards"}},
        {"--sides 6,6 --out " + out.string(), {"--sides", "twice"}},
        {"--set shell.depth=0.1 --out " + out.string(), {"shell.depth", "not a scene field"}},
        {"--set shell.depth_m --out " + out.string(), {"FIELD=VALUES"}},
        {"--seed 1,2 --seeds 3 --out " + out.string(), {"--seed", "--seeds"}},
        {"--from " + out.string() + " --shard 5/4", {"--shard 5/4", "K/N"}},
        {"--from " + out.string(), {out.string(), "no sweep plan"}},
        {"--fill 0.5 --from " + out.string(), {"not allowed with --from"}},
        {"--fill 0.5", {"exactly one of --out"}},
        // Points no run could use are refused up front, not found afterwards as failed rows.
        {"--fill 25,50 --angle 14 --out " + out.string(), {"fill.ratio = 25 (from --fill)", "from 0 to 1", "2 of 2 runs"}},
        {"--fill 0,5 --out " + out.string(), {"fill.ratio = 5", "1 of 2 runs"}},
        {"--sides 6 --seed 99999999999999999999 --out " + out.string(), {"run.seed", "0 to 2^64-1"}},
        // CLI11's words replaced by the program's, pointing at the command's help.
        {"--jobs two --out " + out.string(), {"--jobs two: not a whole number", "see polyroll sweep --help"}},
        {"--seeds 0 --out " + out.string(), {"--seeds 0 is out of range (allowed: 1 to 100000)"}},
        {"--force --out " + out.string(), {"unknown flag '--force'"}},
        // --jobs 0 refused as tradeoff refuses it, not read as "all cores".
        {"--jobs 0 --out " + out.string(), {"--jobs 0 is out of range (allowed: 1 to 1024)", "see polyroll sweep --help"}},
        {"--jobs 1025 --out " + out.string(), {"--jobs 1025 is out of range (allowed: 1 to 1024)"}},
        // One name for the field flag: --param was an alias of --set.
        {"--param shell.depth_m=0.05 --out " + out.string(), {"unknown flag '--param'"}},
        // A plan over the bounds needs --large: 62 x 101 x 179 x 5 runs (a plan.json of about 900 MB), or
        // 420 runs of up to an hour simulated each on one core.
        {"--sides 3:64:1 --fill 0:1:0.01 --angle 0:89:0.5 --seeds 5 --plan-only --out " + out.string(),
         {"5604490 runs", "--sides 62 x --fill 101 x --angle 179 x --seeds 5", "more than 100000", "--large"}},
        {"--fill 0.5 --angle 10:30:1 --seeds 20 --time-limit 3600 --jobs 1 --out " + out.string(),
         {"420 runs estimated at up to", "more than 100 h", "--large to confirm"}},
    };
    for (const Case& c : cases) polyroll::test::expect_refused(kPolyrollExe + " sweep " + c.args, c.words, out);
    // A non-empty folder that is no sweep: the message suggests what sweep has, not --force.
    fs::create_directories(out);
    std::ofstream(out / "notes.txt") << "mine";
    const Result full = shell(kPolyrollExe + " sweep --fill 0 --out " + out.string());
    INFO(full.out);
    CHECK(full.exit_code == 2);
    CHECK_THAT(full.out, Catch::Contains("not empty") && Catch::Contains("a new or empty folder"));
    CHECK_THAT(full.out, !Catch::Contains("--force"));
    CHECK_FALSE(fs::exists(out / "plan.json"));
    fs::remove_all(out);
    // A folder holding another sweep is not overwritten.
    REQUIRE(shell(kPolyrollExe + " sweep --sides 6 --fill 0 --out " + out.string() + " --plan-only").exit_code == 0);
    const std::string before = read_file(out / "plan.json");
    const Result other = shell(kPolyrollExe + " sweep --sides 8 --fill 0 --out " + out.string());
    INFO(other.out);
    CHECK(other.exit_code == 2);
    CHECK_THAT(other.out, Catch::Contains("holds a different sweep"));
    CHECK(read_file(out / "plan.json") == before);
    fs::remove_all(out);
}

TEST_CASE("sweep: more values for the same flags extend a finished sweep and keep its runs", "[sweep][cli]") {
    const fs::path out = sweep_cli_scratch("extend");
    const std::string common = " --sides 6 --fill 0 --fidelity draft --time-limit 0.2 -q --jobs 1 --out " + out.string();
    REQUIRE(shell(kPolyrollExe + " sweep --angle 20" + common).exit_code == 0);
    const std::string first_row = read_file(out / "results.csv").substr(read_file(out / "results.csv").find('\n') + 1);
    // 10 deg sorts before 20: the finished run moves to index 1 and is not run again.
    const Result wider = shell(kPolyrollExe + " sweep --angle 10,20,30" + common);
    INFO(wider.out);
    REQUIRE(wider.exit_code == 0);
    CHECK_THAT(wider.out, Catch::Contains("extends the sweep") && Catch::Contains("1 runs were planned there, 3 now"));
    CHECK_THAT(wider.out, Catch::Contains("2 of 2 runs done in this session") && Catch::Contains("1 found done before"));
    const std::string table = read_file(out / "results.csv");
    CHECK(std::count(table.begin(), table.end(), '\n') == 4);  // header and three rows
    // The kept row, re-indexed from 0 to 1, otherwise byte for byte (its wall time included).
    CHECK_THAT(table, Catch::Contains("\n1" + first_row.substr(first_row.find(','))));
    CHECK(polyroll::sweep::read_plan(out).runs.size() == 3);
    // Fewer values, or another field, is still a different sweep, refused with nothing changed.
    const std::string plan_before = read_file(out / "plan.json");
    for (const std::string& args : {std::string(" --angle 10,20"), std::string(" --angle 10,20,30 --seeds 2")}) {
        const Result other = shell(kPolyrollExe + " sweep" + args + common);
        INFO(args << "\n" << other.out);
        CHECK(other.exit_code == 2);
        CHECK_THAT(other.out, Catch::Contains("holds a different sweep") && Catch::Contains("more values to extend it"));
        CHECK(read_file(out / "plan.json") == plan_before);
    }
    fs::remove_all(out);
}

TEST_CASE("sweep: the grid and its time echoed first, lists out of order run ascending, all failed exits 1",
          "[sweep][cli]") {
    const fs::path out = sweep_cli_scratch("echo");
    const Result r = shell(kPolyrollExe + " sweep --fill 0 --angle 12,5 --fidelity draft --time-limit 0.1 -q --jobs 1 --out " +
                           out.string());
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    const std::size_t grid = r.out.find("polyroll sweep: 2 runs:");
    const std::size_t done = r.out.find("runs done in this session");
    CHECK(grid != std::string::npos);
    CHECK(grid < done);  // before running
    CHECK_THAT(r.out, Catch::Contains("--angle 5, 12") && Catch::Contains("--angle 12,5 runs in ascending order"));
    CHECK_THAT(r.out, Catch::Contains("estimated at most"));
    const std::string table = read_file(out / "results.csv");
    REQUIRE(table.find(",12,") != std::string::npos);
    CHECK(table.find(",5,") < table.find(",12,"));
    // Nothing but the sweep's files is left: an empty results.csv.lock read as a sweep still running.
    CHECK_FALSE(fs::exists(out / "results.csv.lock"));
    fs::remove_all(out);

    // A plan whose points cannot run (written by another version, or edited): run from the folder, every run
    // fails: exit 1 and the first reason on screen, not exit 0 and a table to open.
    using namespace polyroll::sweep;
    const SweepPlan plan = make_grid_plan(nlohmann::ordered_json::object(),
                                          {SweepAxis{"fill.ratio", "--fill", {25, 50}}});
    fs::create_directories(out);
    write_plan(out, plan);
    const Result failed = shell(kPolyrollExe + " sweep -q --jobs 1 --from " + out.string());
    INFO(failed.out);
    CHECK(failed.exit_code == 1);
    CHECK_THAT(failed.out, Catch::Contains("first failure  invalid point: fill.ratio = 25"));
    CHECK_THAT(failed.out, Catch::Contains("every run failed; the first: invalid point: fill.ratio = 25"));
    fs::remove_all(out);
}

TEST_CASE("sweep: a plan that sets a field on some runs only runs from its folder", "[sweep][cli]") {
    // As the cross-section study's plan sets closure.preset on its closure column only: the others run
    // the base scene's value, and the grid's echo says so.
    using namespace polyroll::sweep;
    const fs::path out = sweep_cli_scratch("field-on-some-runs");
    SweepPlan plan;
    plan.base = {{"fill", {{"ratio", 0}}}, {"fidelity", {{"preset", "draft"}}}, {"run", {{"time_limit_s", 0.1}}}};
    plan.fields = plan.flags = {"ramp.angle_deg", "run.seed"};
    add_run(plan, {{"ramp.angle_deg", 5}});
    add_run(plan, {{"ramp.angle_deg", 5}, {"run.seed", 2}});
    fs::create_directories(out);
    write_plan(out, plan);
    const Result r = shell(kPolyrollExe + " sweep -q --jobs 1 --from " + out.string());
    INFO(r.out);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("polyroll sweep: 2 runs: ramp.angle_deg 5 x run.seed (base), 2"));
    fs::remove_all(out);
}

TEST_CASE("sweep: results.csv names the model each run used and no preset polygon for another n", "[sweep][cli]") {
    const fs::path out = sweep_cli_scratch("model-used");
    const Result r = shell(kPolyrollExe + " sweep --sides 6,7 --fill 0,0.25 --fidelity draft --time-limit 0.1 -q --jobs 2 "
                           "--out " + out.string());
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    const std::string table = read_file(out / "results.csv");
    INFO(table);
    const auto lines = [&] {
        std::vector<std::vector<std::string>> rows;
        std::istringstream in(table);
        for (std::string line; std::getline(in, line);) {
            std::vector<std::string> cells;
            std::stringstream ls(line);
            for (std::string cell; std::getline(ls, cell, ',');) cells.push_back(cell);
            rows.push_back(cells);
        }
        return rows;
    }();
    REQUIRE(lines.size() == 5);
    const auto col = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(lines[0].begin(), lines[0].end(), name) - lines[0].begin());
    };
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const auto& row = lines[i];
        CHECK(row[col("model")] == "auto");  // as asked
        // auto: an empty shell runs the rigid model, a partly filled one the grains.
        CHECK(row[col("model_used")] == (row[col("fill_ratio")] == "0" ? "rigid" : "grains"));
        CHECK(row[col("polygon")] == (row[col("sides")] == "6" ? "hexagon-small" : "custom"));
    }
    fs::remove_all(out);
}
