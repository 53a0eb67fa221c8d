// polyroll figures: the PNG figures of a sweep folder (distance against angle, terminal velocity
// against fill, the behaviour map, speed against time), drawn by src/figures/polyroll_figures.py.
#include <filesystem>
#include <set>

#include <fmt/format.h>

#include "cli/commands.h"
#include "figures/figures_script.h"
#include "sim/atomic_file.h"
#include "sim/errors.h"
#include "sweep/results_table.h"
#include "sweep/sweep_plan.h"
#include "sweep/sweep_runner.h"

namespace polyroll::cli {

namespace {

namespace fs = std::filesystem;

struct FiguresArgs {
    std::string sweep_dir;
    std::string out = "figures";
    std::string runs;
    bool force = false;
};

// The runs shown against time: the ids given, or one per behaviour, all from the scene group (sides,
// material, fill, model, fidelity) of the first run that rolled and then stopped, when there is one.
std::vector<std::size_t> chosen_runs(const sweep::SweepPlan& plan, const sweep::TableFile& t, const std::string& ids) {
    auto col = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(t.header.begin(), t.header.end(), name) - t.header.begin());
    };
    std::vector<std::size_t> out;
    if (!ids.empty()) {
        std::size_t pos = 0;
        while (pos <= ids.size()) {
            const std::size_t comma = std::min(ids.find(',', pos), ids.size());
            const std::string id = ids.substr(pos, comma - pos);
            pos = comma + 1;
            const auto it = std::find_if(plan.runs.begin(), plan.runs.end(), [&](const auto& r) { return r.id == id; });
            if (it == plan.runs.end())
                throw InputError(fmt::format("--runs: '{}' is not a run id of this sweep (allowed: ids from the "
                                             "run_id column of results.csv)", id));
            out.push_back(it->index);
        }
        return out;
    }
    const std::size_t status = col("status"), behaviour = col("behaviour");
    const std::vector<std::size_t> group_cols = {col("sides"), col("material"), col("fill_ratio"), col("model"),
                                                 col("fidelity"), col("polygon"), col("ramp")};
    auto group = [&](const std::vector<std::string>& row) {
        std::string g;
        for (std::size_t c : group_cols) g += row.at(c) + "|";
        return g;
    };
    std::string want;
    for (const auto& row : t.rows)
        if (row.at(status) == "ok" && row.at(behaviour) == "stopped") {
            want = group(row);
            break;
        }
    for (const char* b : {"stopped_at_first_impact", "stopped", "rolled_to_end"}) {
        const std::vector<std::string>* pick = nullptr;
        for (const auto& row : t.rows) {
            if (row.at(status) != "ok" || row.at(behaviour) != b) continue;
            if (!pick) pick = &row;
            if (group(row) == want) {
                pick = &row;
                break;
            }
        }
        if (pick) out.push_back(std::stoull(pick->at(0)));
    }
    return out;
}

int run(const FiguresArgs& a) {
    const fs::path dir = a.sweep_dir;
    const sweep::SweepPlan plan = sweep::read_plan(dir);
    const fs::path results = dir / "results.csv";
    const sweep::TableFile table = sweep::read_table(results);
    if (table.rows.empty())
        throw InputError(fmt::format("{}: no results yet (allowed: a sweep folder with results.csv; run the sweep, or "
                                     "'polyroll sweep --merge {}' after shards)", results.string(), a.sweep_dir));
    const std::vector<std::size_t> runs = chosen_runs(plan, table, a.runs);
    // Checked before the output folder is made: a missing matplotlib leaves nothing behind.
    figures::figures_python();
    figures::figures_script();
    const auto created = prepare_output_dir(a.out, a.force);
    try {
        std::vector<std::string> args = {"sweep", results.string(), a.out};
        for (std::size_t i : runs) {
            const sweep::PlannedRun& run = plan.runs[i];
            fs::path run_dir = dir / "runs" / run.id;
            if (!fs::exists(run_dir / "trajectory.csv")) {
                // The sweep kept no trajectory: run the scene again (same scene, same bytes).
                run_dir = fs::path(a.out) / "runs" / run.id;
                const sweep::RunRecord rec = sweep::execute_run(plan, run, run_dir, true);
                if (!rec.result)
                    throw std::runtime_error(fmt::format("run {} could not be run again: {}", run.id, rec.reason));
            }
            args.push_back("--trajectory");
            args.push_back(run_dir.string());
        }
        const int code = figures::run_figures_script(args);
        if (code != 0) throw std::runtime_error(fmt::format("the figure script failed (exit code {})", code));
    } catch (...) {
        std::error_code ec;
        if (created) fs::remove_all(*created, ec);
        throw;
    }
    return kExitOk;
}

}  // namespace

Action add_figures_command(CLI::App& app) {
    auto a = std::make_shared<FiguresArgs>();
    CLI::App* sub = app.add_subcommand("figures", "draw the PNG figures of a sweep folder (python3-matplotlib)");
    sub->footer(
        "Figures: distance_vs_angle.png, terminal_velocity_vs_fill.png, behaviour_map.png, speed_vs_time.png.\n"
        "Example:\n"
        "  polyroll figures sweeps/grid --out figures/\n"
        "Runs shown against time whose trajectory the sweep did not keep (sweep --trajectories) are run again\n"
        "into OUT/runs/<id>/. Exit codes: 0 done, 2 bad input, 1 other failure (e.g. matplotlib missing).");
    sub->add_option("sweep", a->sweep_dir, "sweep folder (with plan.json and results.csv)")->required();
    sub->add_option("--out", a->out, "folder for the PNG files (default: figures)");
    sub->add_option("--runs", a->runs, "run ids for speed_vs_time.png, comma-separated (default: one run per "
                                       "behaviour)");
    sub->add_flag("--force", a->force, "write into an existing non-empty --out folder");
    return [a] { return run(*a); };
}

}  // namespace polyroll::cli
