// The sweep's thread pool: see sweep_runner.h.
#include "sweep/sweep_runner.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <mutex>
#include <numeric>
#include <set>
#include <thread>

#include <fmt/core.h>

#include "sim/files/atomic_file.h"
#include "sim/errors.h"
#include "sim/model_registry.h"
#include "sim/files/results_io.h"
#include "sim/run_cores.h"
#include "sweep/merge.h"
#include "sweep/progress.h"
#include "sweep/run_cost.h"
#include "sweep/table_writer.h"

namespace polyroll::sweep {

namespace fs = std::filesystem;

fs::path table_path(const fs::path& dir, const std::optional<std::pair<int, int>>& shard) {
    if (!shard) return dir / "results.csv";
    return dir / "shards" / fmt::format("shard-{}-of-{}.csv", shard->first, shard->second);
}

std::vector<fs::path> table_paths(const fs::path& dir) {
    std::vector<fs::path> out;
    std::error_code ec;
    if (fs::is_regular_file(dir / "results.csv", ec)) out.push_back(dir / "results.csv");
    std::vector<fs::path> shards;
    if (fs::is_directory(dir / "shards", ec))
        for (const auto& e : fs::directory_iterator(dir / "shards", ec))
            if (e.is_regular_file() && e.path().extension() == ".csv") shards.push_back(e.path());
    std::sort(shards.begin(), shards.end());
    out.insert(out.end(), shards.begin(), shards.end());
    return out;
}

namespace {

// One point, run and its files written; a point that cannot be run is a failed record, never a throw.
RunRecord attempt_run(const SweepPlan& plan, const PlannedRun& run, const fs::path& run_dir, bool trajectories) {
    RunRecord rec;
    try {
        const Scene scene = resolve_scene(run_layers(plan, run));
        RunResult r = run_scene(scene);
        rec.wall_time_s = r.wall_time_s;
        rec.ok = r.measured.behaviour != Behaviour::diverged;
        if (!rec.ok) rec.reason = "diverged: " + r.measured.divergence;
        // A run the caller ended early is ok; its row says so where a failure would say why.
        else if (!r.measured.ended_early.empty()) rec.reason = r.measured.ended_early;
        if (!run_dir.empty()) {
            fs::create_directories(run_dir);
            write_file_atomic(run_dir / "summary.json", summary_json(r).dump(2) + "\n");
            write_file_atomic(run_dir / "impacts.csv", impacts_csv(r));
            if (trajectories) write_file_atomic(run_dir / "trajectory.csv", trajectory_csv(r));
        }
        rec.result = std::move(r);
        return rec;
    } catch (const InputError& e) {
        rec.reason = std::string("invalid point: ") + e.what();
    } catch (const std::exception& e) {
        rec.reason = std::string("error: ") + e.what();
    }
    rec.ok = false;
    rec.result.reset();
    return rec;
}

}  // namespace

RunRecord execute_run(const SweepPlan& plan, const PlannedRun& run, const fs::path& run_dir, bool trajectories) {
    const auto start = std::chrono::steady_clock::now();
    RunRecord rec = attempt_run(plan, run, run_dir, trajectories);
    // A failed point has no simulation time of its own: it costs what it took to fail.
    if (!rec.result)
        rec.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return rec;
}

SweepReport run_sweep(const SweepPlan& plan, const SweepOptions& o, const std::atomic<bool>* stop) {
    const auto start = std::chrono::steady_clock::now();
    SweepReport report;
    report.table = table_path(o.dir, o.shard);
    const ResultsTable table(plan);
    fs::create_directories(report.table.parent_path());

    std::vector<std::size_t> slice;
    if (o.shard)
        slice = shard_indices(plan.runs.size(), o.shard->first, o.shard->second);
    else {
        slice.resize(plan.runs.size());
        std::iota(slice.begin(), slice.end(), std::size_t{0});
    }
    report.planned = slice.size();

    TableWriter writer(report.table, table.columns(), o.retry_failed);
    // Finished anywhere in the folder: this table, the full table, other shards' tables.
    std::set<std::size_t> finished;
    const std::size_t status_col = table.column("status");
    auto note = [&](const std::vector<std::string>& row) {
        const std::size_t i = std::stoull(row.at(0));
        if (i < plan.runs.size() && plan.runs[i].id == row.at(1) && !(o.retry_failed && row.at(status_col) == "failed"))
            finished.insert(i);
    };
    for (const auto& row : writer.existing_rows()) note(row);
    for (const fs::path& p : table_paths(o.dir)) {
        if (fs::equivalent(p, report.table)) continue;
        const TableFile t = read_table(p);
        if (t.header == table.columns())
            for (const auto& row : t.rows) note(row);
    }
    std::vector<std::size_t> todo;
    for (std::size_t i : slice)
        if (!finished.count(i)) todo.push_back(i);
    report.already = slice.size() - todo.size();
    if (!o.expected_s.empty()) {
        auto expected = [&](std::size_t i) { return i < o.expected_s.size() ? o.expected_s[i] : -1.0; };
        std::stable_sort(todo.begin(), todo.end(), [&](std::size_t a, std::size_t b) { return expected(a) > expected(b); });
    }

    // Each run's estimated cost, so the time left weighs the runs left by what they cost.
    std::vector<double> cost(todo.size());
    for (std::size_t k = 0; k < todo.size(); ++k) cost[k] = max_run_seconds(plan, plan.runs[todo[k]]);
    const int jobs = std::max(1, std::min<int>(o.jobs, static_cast<int>(std::max<std::size_t>(todo.size(), 1))));
    Progress progress(todo.size(), report.already, o.quiet, stderr, std::accumulate(cost.begin(), cost.end(), 0.0),
                      jobs);
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    std::atomic<bool> abort{false};
    // The failed run first in the plan, whichever thread ran it: the same reason on every machine.
    std::size_t first_failed_index = plan.runs.size();
    // The cores are shared among the jobs: a run that can use more than one (the 3D reference's
    // threads) gets its share (sim/run_cores.h).
    const int cores_per_run = std::max(1, process_cores() / jobs);
    auto worker = [&] {
        const ScopedRunCores cores(cores_per_run);
        for (;;) {
            if (abort || (stop && *stop)) return;
            const std::size_t k = next++;
            if (k >= todo.size()) return;
            const PlannedRun& run = plan.runs[todo[k]];
            try {
                const RunRecord rec = execute_run(plan, run, o.dir / "runs" / run.id, o.trajectories);
                writer.append(table.row_line(run, rec));
                progress.run_done(!rec.ok, cost[k], rec.wall_time_s);
                if (!rec.ok) {
                    std::lock_guard<std::mutex> g(error_mutex);
                    if (run.index < first_failed_index) {
                        first_failed_index = run.index;
                        report.first_failure = rec.reason;
                    }
                }
            } catch (...) {
                // The table or a run's files could not be written: stop, keep what is safe.
                std::lock_guard<std::mutex> g(error_mutex);
                if (!error) error = std::current_exception();
                abort = true;
                return;
            }
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(static_cast<std::size_t>(jobs));
    for (int j = 0; j < jobs; ++j) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    progress.finish();
    writer.close_sorted();
    if (error) std::rethrow_exception(error);

    report.ran = progress.done();
    report.failed = progress.failed();
    report.interrupted = report.ran < todo.size();
    if (!o.shard && !report.interrupted && table_paths(o.dir).size() > 1) merge_tables(plan, o.dir);
    report.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

}  // namespace polyroll::sweep
