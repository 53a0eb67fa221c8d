// The sweep engine: value lists and ranges, deterministic plans with stable ids, shards that cover a
// plan exactly once, results tables that survive a crash, resumption without duplicates, failed runs
// recorded with their reason, and merged shards equal to the one-process table.
#include <catch2/catch.hpp>

#include "test_helpers.h"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include "sim/errors.h"
#include "sweep/grid_values.h"
#include "sweep/merge.h"
#include "sweep/progress.h"
#include "sweep/results_table.h"
#include "sweep/sweep_plan.h"
#include "sweep/sweep_runner.h"
#include "sweep/table_writer.h"

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;
using namespace polyroll;
using namespace polyroll::sweep;

namespace {

using polyroll::test::read_file;
using polyroll::test::table_without_wall_time;

const polyroll::test::Scratch sweep_scratch("sweep-");

// A cheap grid: empty shells and a few grains, short runs; one point out of range. Standard fidelity:
// at draft a grain of a filled shell tumbling at 30 deg slips through a wall now and then (measured: 2
// of 18 runs at 35-45 deg), and this grid's in-range points must all finish.
SweepPlan tiny_plan() {
    json base = {{"fidelity", "standard"}, {"run", {{"time_limit_s", 0.6}}}, {"ramp", {{"preset", "wooden"}}}};
    std::vector<SweepAxis> axes = {
        {"shell.sides", "--sides", {6, 8}},
        {"fill.ratio", "--fill", {0.0, 0.1, 1.5}},
        {"ramp.angle_deg", "--angle", {8.0, 30.0}},
        {"run.seed", "--seeds", {1u, 2u}},
    };
    return make_grid_plan(base, axes);
}

}  // namespace

TEST_CASE("grid values: lists, inclusive ranges without accumulated error, types kept", "[sweep]") {
    auto v = parse_grid_values("--fill", "0:1:0.1");
    REQUIRE(v.size() == 11);
    CHECK(v.back().get<double>() == 1.0);
    CHECK(value_text(v[3]) == "0.3");
    CHECK(value_text(v[7]) == "0.7");
    auto eighths = parse_grid_values("--fill", "0:1:0.125");
    CHECK(eighths.size() == 9);
    auto sides = parse_grid_values("--sides", "6,8,10:18:4");
    REQUIRE(sides.size() == 5);
    CHECK(sides[0].is_number_unsigned());
    CHECK(sides[4] == 18);
    auto angles = parse_grid_values("--angle", "5:30:1");
    CHECK(angles.size() == 26);
    auto mixed = parse_grid_values("--material", "bb, rice,peas");
    REQUIRE(mixed.size() == 3);
    CHECK(mixed[1] == "rice");
    CHECK(parse_grid_values("--angle", "2.5")[0].get<double>() == 2.5);
    // null unsets an optional field (column discs against two grains per disc).
    auto per_disc = parse_grid_values("--set fill.material.grains_per_disc", "null,2");
    REQUIRE(per_disc.size() == 2);
    CHECK(per_disc[0].is_null());
    CHECK(per_disc[1] == 2);
    CHECK(value_text(per_disc[0]) == "null");
    // A range whose stop is not on the grid stops below it.
    auto partial = parse_grid_values("--angle", "0:1:0.3");
    REQUIRE(partial.size() == 4);
    CHECK(partial.back().get<double>() == Approx(0.9));
    // 1e-9 of a step short of the stop still reaches it; a third of a step does not.
    CHECK(inclusive_range("x", 0.0, 0.3, 0.1).size() == 4);

    auto message = [](const std::string& name, const std::string& text) {
        try {
            parse_grid_values(name, text);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CHECK_THAT(message("--fill", "0:1:0"), Catch::Contains("--fill") && Catch::Contains("step 0"));
    CHECK_THAT(message("--angle", "30:5:1"), Catch::Contains("backwards"));
    CHECK_THAT(message("--angle", "5:30"), Catch::Contains("'5:30' is not a range"));
    CHECK_THAT(message("--sides", "6,,8"), Catch::Contains("empty item"));
    CHECK_THAT(message("--angle", "0:1e9:1e-3"), Catch::Contains("at most"));
}

TEST_CASE("plans: deterministic order and ids, last axis fastest, duplicates refused", "[sweep]") {
    const SweepPlan a = tiny_plan(), b = tiny_plan();
    REQUIRE(a.runs.size() == 2 * 3 * 2 * 2);
    CHECK(plan_to_json(a) == plan_to_json(b));
    std::set<std::string> ids;
    for (const auto& r : a.runs) ids.insert(r.id);
    CHECK(ids.size() == a.runs.size());
    CHECK(a.runs[0].point == json({{"shell.sides", 6}, {"fill.ratio", 0.0}, {"ramp.angle_deg", 8.0}, {"run.seed", 1u}}));
    CHECK(a.runs[1].point["run.seed"] == 2u);
    CHECK(a.runs[2].point["ramp.angle_deg"] == 30.0);
    CHECK(a.runs.back().point["shell.sides"] == 8);
    // The id depends on the point and the base, not on the point's place in the plan.
    const SweepPlan one = make_grid_plan(a.base, {{"shell.sides", "--sides", {8}},
                                                  {"fill.ratio", "--fill", {1.5}},
                                                  {"ramp.angle_deg", "--angle", {30.0}},
                                                  {"run.seed", "--seeds", {2u}}});
    CHECK(one.runs[0].id == a.runs.back().id);
    json other_base = a.base;
    other_base["ramp"]["preset"] = "air-track";
    CHECK(run_id(other_base, a.runs[0].point) != a.runs[0].id);

    CHECK_THROWS_WITH(make_grid_plan(json::object(), {{"shell.sides", "--sides", {6, 6}}}),
                      Catch::Contains("--sides") && Catch::Contains("given twice"));
    CHECK_THROWS_AS(check_scene_field("shell.depth", "--set shell.depth"), InputError);
    CHECK_NOTHROW(check_scene_field("shell.depth_m", "--set shell.depth_m"));
    CHECK_NOTHROW(check_scene_field("fill.material.diameter_m", "--set"));

    // Read back, it is the same plan; a hand-edited point is caught.
    CHECK(plan_to_json(plan_from_json(plan_to_json(a), "t")) == plan_to_json(a));
    json edited = plan_to_json(a);
    edited["runs"][3]["point"]["ramp.angle_deg"] = 31.0;
    CHECK_THROWS_WITH(plan_from_json(edited, "plan.json"), Catch::Contains("run 3"));
}

TEST_CASE("shards: disjoint slices that together cover the plan once", "[sweep]") {
    for (std::size_t runs : {0u, 1u, 7u, 100u}) {
        for (int n : {1, 3, 16}) {
            std::vector<int> seen(runs, 0);
            for (int k = 1; k <= n; ++k)
                for (std::size_t i : shard_indices(runs, k, n)) ++seen.at(i);
            for (int s : seen) CHECK(s == 1);
        }
    }
    CHECK(parse_shard("3/16") == std::make_pair(3, 16));
    for (const char* bad : {"0/4", "5/4", "3", "a/b", "3/16x", "-1/2"})
        CHECK_THROWS_WITH(parse_shard(bad), Catch::Contains(bad) && Catch::Contains("K/N"));
}

TEST_CASE("results tables: CSV cells round-trip, and a line cut short is dropped", "[sweep]") {
    const std::vector<std::string> cells = {"3", "a,b", "say \"hi\"", "", " padded ", "line\nbreak"};
    std::string line = csv_line(cells);
    line.pop_back();
    auto back = parse_csv_line(line);
    REQUIRE(back.size() == cells.size());
    CHECK(back[1] == "a,b");
    CHECK(back[2] == "say \"hi\"");
    CHECK(back[4] == " padded ");
    CHECK(back[5] == "line break");

    const fs::path dir = sweep_scratch("partial");
    fs::create_directories(dir);
    std::ofstream(dir / "t.csv") << "index,x\n0,a\n1,b\n2,c";  // the last row lost its newline
    TableFile t = read_table(dir / "t.csv");
    CHECK(t.rows.size() == 2);
    CHECK(t.had_partial_line);
    // Columns by name: a missing one is said with the file's name (figures and scoring read them so).
    CHECK(column_index(t, "x") == 1);
    CHECK(cell(t, t.rows.at(1), "x") == "b");
    CHECK(cell(t, t.rows.at(1), "status").empty());
    CHECK(test::input_error_of([&] { column_index(t, "status"); }) ==
          (dir / "t.csv").string() + ": no column status (allowed: a polyroll results table, which has it)");
    std::ofstream(dir / "bad.csv") << "index,x\n0,a,b\n";
    CHECK_THROWS_AS(read_table(dir / "bad.csv"), InputError);
    fs::remove_all(dir);
}

TEST_CASE("the table writer only ever replaces the table whole, and no row waits long in memory", "[sweep]") {
    const fs::path dir = sweep_scratch("writer");
    fs::create_directories(dir);
    const fs::path path = dir / "results.csv";
    const std::vector<std::string> header{"index", "run_id", "status", "wall_time_s"};
    std::ofstream(path) << "index,run_id,status,wall_time_s\n1,b,ok,0.5\n0,a,fail";  // cut short by an old writer
    {
        TableWriter w(path, header, false, std::chrono::milliseconds(300));
        REQUIRE(w.existing_rows().size() == 1);
        TableFile t = read_table(path);
        CHECK_FALSE(t.had_partial_line);  // replaced whole on opening: the torn line is gone
        CHECK(t.rows.size() == 1);
        w.append("0,a,ok,0.25\n");
        // Without another row or close, the flusher replaces the table within the delay (300 ms);
        // wait up to 20 s so that a loaded machine cannot fail this.
        for (int i = 0; i < 200 && read_table(path).rows.size() < 2; ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        t = read_table(path);
        REQUIRE(t.rows.size() == 2);
        CHECK(t.rows[0][0] == "0");  // sorted by index on every replacement
        CHECK_FALSE(t.had_partial_line);
        // A second writer is refused while this one holds the table.
        CHECK_THROWS_AS(TableWriter(path, header, false), InputError);
        CHECK(fs::exists(path.string() + ".lock"));  // the refused writer leaves the holder's lock alone
        w.append("2,c,failed,0.1\n");
        w.close_sorted();
        CHECK(read_table(path).rows.size() == 3);
        // Closed, the lock file goes: an empty results.csv.lock left behind read as a sweep still running.
        CHECK_FALSE(fs::exists(path.string() + ".lock"));
    }
    // Reopened with drop_failed, the failed row goes (to be run again).
    TableWriter again(path, header, true);
    CHECK(again.existing_rows().size() == 2);
    again.close_sorted();
    CHECK(read_table(path).rows.size() == 2);
    {
        // Left without close_sorted (an exception on the way out), the lock file goes too.
        TableWriter dropped(path, header, false);
    }
    CHECK_FALSE(fs::exists(path.string() + ".lock"));
    // No temporaries are left beside the table.
    for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().filename().string().find(".tmp-") == std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("a sweep records failed points, survives a crash and resumes without duplicates", "[sweep]") {
    const SweepPlan plan = tiny_plan();
    const ResultsTable columns(plan);
    const fs::path dir = sweep_scratch("resume");
    SweepOptions o;
    o.dir = dir;
    o.jobs = 2;
    o.quiet = true;
    const SweepReport first = run_sweep(plan, o, nullptr);
    CHECK(first.ran == plan.runs.size());
    CHECK_FALSE(first.interrupted);
    const std::string full = read_file(dir / "results.csv");
    const TableFile t = read_table(dir / "results.csv");
    REQUIRE(t.rows.size() == plan.runs.size());
    const std::size_t status = columns.column("status"), reason = columns.column("reason"),
                      fill = columns.column("fill_ratio"), behaviour = columns.column("behaviour");
    std::size_t failed = 0;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
        const auto& row = t.rows[i];
        CHECK(row[0] == std::to_string(i));  // sorted by plan index
        if (row[fill] == "1.5") {
            ++failed;
            CHECK(row[status] == "failed");
            CHECK_THAT(row[reason], Catch::Contains("fill.ratio = 1.5") && Catch::Contains("--fill"));
            CHECK_FALSE(fs::exists(dir / "runs" / row[1]));
        } else {
            CHECK(row[status] == "ok");
            CHECK(row[behaviour] != "diverged");
            CHECK(fs::exists(dir / "runs" / row[1] / "summary.json"));
        }
    }
    CHECK(failed == first.failed);
    CHECK(failed == 8);

    // A crash: two rows written in completion order, then half a row.
    {
        std::istringstream in(full);
        std::string header, r0, r1, r2;
        std::getline(in, header);
        std::getline(in, r0);
        std::getline(in, r1);
        std::getline(in, r2);
        std::ofstream(dir / "results.csv", std::ios::trunc) << header << "\n" << r1 << "\n" << r0 << "\n"
                                                            << r2.substr(0, r2.size() / 2);
    }
    const SweepReport resumed = run_sweep(plan, o, nullptr);
    CHECK(resumed.already == 2);
    CHECK(resumed.ran == plan.runs.size() - 2);
    CHECK(table_without_wall_time(read_file(dir / "results.csv")) == table_without_wall_time(full));

    // Nothing left: the same sweep again runs nothing and leaves the table as it was.
    const SweepReport again = run_sweep(plan, o, nullptr);
    CHECK(again.ran == 0);
    CHECK(table_without_wall_time(read_file(dir / "results.csv")) == table_without_wall_time(full));

    // Stopped before it starts (Ctrl-C): nothing run, reported as interrupted; --retry-failed reruns
    // exactly the failed rows.
    std::atomic<bool> stop{true};
    SweepOptions retry = o;
    retry.retry_failed = true;
    const SweepReport stopped = run_sweep(plan, retry, &stop);
    CHECK(stopped.interrupted);
    CHECK(stopped.ran == 0);
    const SweepReport retried = run_sweep(plan, retry, nullptr);
    CHECK(retried.ran == failed);
    CHECK(table_without_wall_time(read_file(dir / "results.csv")) == table_without_wall_time(full));
    fs::remove_all(dir);
}

TEST_CASE("shards merged give the one-process table, and tables of another plan are refused", "[sweep]") {
    const SweepPlan plan = tiny_plan();
    const fs::path one = sweep_scratch("one"), sharded = sweep_scratch("sharded");
    SweepOptions o;
    o.dir = one;
    o.jobs = 1;
    o.quiet = true;
    run_sweep(plan, o, nullptr);

    o.dir = sharded;
    o.jobs = 2;
    for (int k = 1; k <= 3; ++k) {
        o.shard = std::make_pair(k, 3);
        const SweepReport r = run_sweep(plan, o, nullptr);
        CHECK(r.planned == shard_indices(plan.runs.size(), k, 3).size());
        CHECK(fs::exists(sharded / "shards" / ("shard-" + std::to_string(k) + "-of-3.csv")));
    }
    CHECK_FALSE(fs::exists(sharded / "results.csv"));
    const MergeReport m = merge_tables(plan, sharded);
    CHECK(m.missing.empty());
    CHECK(m.rows == plan.runs.size());
    CHECK(m.tables == 4);
    CHECK(table_without_wall_time(read_file(sharded / "results.csv")) == table_without_wall_time(read_file(one / "results.csv")));
    // Merging again changes nothing (no duplicates from results.csv plus the shards).
    merge_tables(plan, sharded);
    CHECK(table_without_wall_time(read_file(sharded / "results.csv")) == table_without_wall_time(read_file(one / "results.csv")));

    // A missing slice is reported, not invented.
    fs::remove(sharded / "shards" / "shard-2-of-3.csv");
    fs::remove(sharded / "results.csv");
    CHECK(merge_tables(plan, sharded).missing == shard_indices(plan.runs.size(), 2, 3));

    // Another plan's table in the folder is refused.
    json base = plan.base;
    base["run"]["time_limit_s"] = 0.7;
    const SweepPlan other = make_grid_plan(base, {{"shell.sides", "--sides", {6, 8}}});
    CHECK_THROWS_AS(merge_tables(other, sharded), InputError);
    fs::remove_all(one);
    fs::remove_all(sharded);
}

TEST_CASE("the time left weighs the runs left by their estimated cost, not by an average run", "[sweep][progress]") {
    // Ten cheap runs done, each estimated at 1 s and taking 0.5 s; one run left estimated at 100 s.
    // An average over the runs done would say 0.5 s left; the estimate scaled by the measured share
    // says 50 s.
    CostTally t;
    t.runs_left = 1;
    t.estimated_left_s = 100.0;
    t.estimated_done_s = 10.0;
    t.measured_done_s = 5.0;
    t.jobs = 2;  // one run left runs on one job whatever the jobs
    REQUIRE(time_left_s(t, 5.0, 10).has_value());
    CHECK(*time_left_s(t, 5.0, 10) == Approx(50.0));
    // The elapsed time does not enter it: the runs' own measured times do (runs slower than their
    // estimate on a loaded machine make every run left slower by the same share).
    CHECK(*time_left_s(t, 500.0, 10) == Approx(50.0));
    t.measured_done_s = 20.0;
    CHECK(*time_left_s(t, 5.0, 10) == Approx(200.0));
    // Several runs left share the jobs.
    t.runs_left = 4;
    t.estimated_left_s = 40.0;
    t.measured_done_s = 10.0;
    CHECK(*time_left_s(t, 5.0, 10) == Approx(40.0 * 1.0 / 2));
    // Nothing finished: no figure yet; nothing left: none.
    CHECK_FALSE(time_left_s(t, 5.0, 0).has_value());
    t.runs_left = 0;
    CHECK(*time_left_s(t, 5.0, 10) == 0.0);
    // Without estimates, this session's pace: 10 runs in 5 s, 4 left.
    CostTally bare;
    bare.runs_left = 4;
    CHECK(*time_left_s(bare, 5.0, 10) == Approx(2.0));
}

TEST_CASE("the progress line's time left follows the runs' costs", "[sweep][progress]") {
    // Into a file (not a terminal): a line at every tenth of the runs. Two runs: a cheap one done in
    // half its estimate, then 100 s of estimate left: "0:50 left", however fast this test runs.
    std::FILE* out = std::tmpfile();
    REQUIRE(out != nullptr);
    {
        Progress p(2, 0, false, out, 101.0, 1);
        p.run_done(false, 1.0, 0.5);
        p.run_done(true, 100.0, 60.0);
        p.finish();
    }
    std::rewind(out);
    std::string text(4096, '\0');
    text.resize(std::fread(text.data(), 1, text.size(), out));
    std::fclose(out);
    INFO(text);
    CHECK_THAT(text, Catch::Contains("1/2 runs, 0 failed") && Catch::Contains("0:50 left"));
    CHECK_THAT(text, Catch::Contains("2/2 runs, 1 failed") && Catch::Contains("0:00 left"));
}
