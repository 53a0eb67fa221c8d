// polyroll figures: the figures of a sweep folder (distance against angle, terminal velocity against
// fill, the behaviour map, speed against time), of one run folder or of one compare folder (speed and
// energy against time), drawn by src/figures/polyroll_figures.py, each with a CSV of what it plots.
#include <filesystem>
#include <fstream>
#include <set>

#include <fmt/core.h>

#include "cli/commands.h"
#include "figures/figures_script.h"
#include "sim/files/atomic_file.h"
#include "sim/errors.h"
#include "sim/model_registry.h"
#include "sim/scene/scene_json.h"
#include "sweep/observations.h"
#include "sweep/results_table.h"
#include "sweep/sweep_plan.h"
#include "sweep/sweep_runner.h"

namespace polyroll::cli {

namespace {

namespace fs = std::filesystem;

struct FiguresArgs {
    std::string folder;
    std::string out = "figures";
    std::string runs;
    std::string format = "png";
    bool force = false;
};

enum class FolderKind { sweep, run, compare };

// The runs of a compare folder: the models `polyroll compare` always runs (model_registry.h).
std::vector<std::string> compare_models() {
    std::vector<std::string> names;
    for (Model m : everyday_models()) names.push_back(to_string(m));
    return names;
}

bool is_run_folder(const fs::path& dir) {
    return fs::is_regular_file(dir / "summary.json") && fs::is_regular_file(dir / "trajectory.csv") &&
           fs::is_regular_file(dir / "impacts.csv");
}

// What `polyroll sweep --out`, `run --out` or `compare --out` left in the folder; InputError otherwise.
FolderKind folder_kind(const std::string& folder) {
    const fs::path dir = folder;
    std::error_code ec;
    if (!fs::exists(dir, ec))
        throw InputError(fmt::format("'{}' does not exist (allowed: a sweep, run or compare folder)", folder));
    if (fs::is_regular_file(dir / "plan.json")) return FolderKind::sweep;
    if (is_run_folder(dir)) return FolderKind::run;
    const std::vector<std::string> models = compare_models();
    if (std::all_of(models.begin(), models.end(), [&](const std::string& m) { return is_run_folder(dir / m); }))
        return FolderKind::compare;
    throw InputError(fmt::format("'{}' is not a sweep, run or compare folder (allowed: a folder with plan.json from "
                                 "polyroll sweep --out, summary.json, trajectory.csv and impacts.csv from polyroll run "
                                 "--out, or {}/ from polyroll compare --out)",
                                 folder, model_list(everyday_models(), "/, ")));
}

// "png", "svg" or both, comma-separated; InputError naming the value otherwise.
void check_format(const std::string& format) {
    std::set<std::string> seen;
    std::size_t pos = 0;
    while (pos <= format.size()) {
        const std::size_t comma = std::min(format.find(',', pos), format.size());
        const std::string f = format.substr(pos, comma - pos);
        pos = comma + 1;
        if ((f != "png" && f != "svg") || !seen.insert(f).second)
            throw InputError(fmt::format("--format: '{}' is not allowed (allowed: png, svg or png,svg)", format));
    }
}

// What the script cannot read from results.csv: each run's ramp length (a run that rolled to the end
// is drawn there) and the experiment's angle-range observations with a linear fit (drawn in the
// panels whose runs match the observation's scene).
nlohmann::json figure_context(const sweep::SweepPlan& plan) {
    nlohmann::json lengths = nlohmann::json::object();
    for (const sweep::PlannedRun& run : plan.runs)
        lengths[run.id] = resolve_scene(sweep::run_layers(plan, run)).ramp.length_m;
    nlohmann::json observations = nlohmann::json::array();
    for (const sweep::Observation& o : sweep::read_observations("").observations) {
        if (!o.angle_range_deg || !o.linear_fit) continue;
        observations.push_back({{"id", o.id},
                                {"scene", o.scene},
                                {"angle_range_deg", {o.angle_range_deg->first, o.angle_range_deg->second}},
                                {"angle_tolerance_deg", o.angle_tolerance_deg},
                                {"linear_fit",
                                 {{"slope_m_per_deg", o.linear_fit->slope_m_per_deg},
                                  {"intercept_m", o.linear_fit->intercept_m}}}});
    }
    return {{"ramp_length_m", lengths}, {"observations", observations}};
}

// The runs shown against time: the ids given, or one per behaviour, all from the scene group (sides,
// material, fill, model, fidelity) of the first run that rolled and then stopped, when there is one.
std::vector<std::size_t> chosen_runs(const sweep::SweepPlan& plan, const sweep::TableFile& t, const std::string& ids) {
    auto col = [&](const std::string& name) { return sweep::column_index(t, name); };
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

int sweep_figures(const FiguresArgs& a) {
    const fs::path dir = a.folder;
    const sweep::SweepPlan plan = sweep::read_plan(dir);
    const fs::path results = dir / "results.csv";
    const sweep::TableFile table = sweep::read_table(results);
    if (table.rows.empty())
        throw InputError(fmt::format("{}: no results yet (allowed: a sweep folder with results.csv; run the sweep, or "
                                     "'polyroll sweep --merge {}' after shards)", results.string(), a.folder));
    const std::vector<std::size_t> runs = chosen_runs(plan, table, a.runs);
    const nlohmann::json context = figure_context(plan);
    // Checked before the output folder is made: a missing matplotlib leaves nothing behind.
    figures::figures_python();
    figures::figures_script();
    const auto created = prepare_output_dir(a.out, a.force);
    // The context goes to the script as a file (a large sweep's would not fit a command line), removed after.
    const fs::path context_file = fs::path(a.out) / ".figures-context.json";
    try {
        write_file_atomic(context_file, context.dump());
        std::vector<std::string> args = {"sweep", results.string(), a.out, "--format", a.format, "--context",
                                         context_file.string()};
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
        fs::remove(context_file);
        if (code != 0) throw std::runtime_error(fmt::format("the figure script failed (exit code {})", code));
    } catch (...) {
        std::error_code ec;
        fs::remove(context_file, ec);
        if (created) fs::remove_all(*created, ec);
        throw;
    }
    return kExitOk;
}

// A run folder or a compare folder: speed and energy against time, one run or the three models.
int run_figures(const FiguresArgs& a, FolderKind kind) {
    if (!a.runs.empty())
        throw InputError(fmt::format("--runs '{}': only for a sweep folder, and '{}' is a {} folder", a.runs, a.folder,
                                     kind == FolderKind::run ? "run" : "compare"));
    figures::figures_python();
    figures::figures_script();
    const auto created = prepare_output_dir(a.out, a.force);
    try {
        std::vector<std::string> args = {kind == FolderKind::run ? "run" : "compare", a.out, "--format", a.format};
        if (kind == FolderKind::run) args.push_back(a.folder);
        else
            for (const std::string& m : compare_models()) args.push_back((fs::path(a.folder) / m).string());
        const int code = figures::run_figures_script(args);
        if (code != 0) throw std::runtime_error(fmt::format("the figure script failed (exit code {})", code));
    } catch (...) {
        std::error_code ec;
        if (created) fs::remove_all(*created, ec);
        throw;
    }
    return kExitOk;
}

int run(const FiguresArgs& a) {
    check_format(a.format);
    const FolderKind kind = folder_kind(a.folder);
    return kind == FolderKind::sweep ? sweep_figures(a) : run_figures(a, kind);
}

}  // namespace

Action add_figures_command(Command& app) {
    auto a = std::make_shared<FiguresArgs>();
    Command sub = app.add_subcommand(
        "figures", "draw the figures of a sweep, run or compare folder, each with a CSV of what it plots "
                   "(python3-matplotlib)");
    sub.footer(
        "A sweep folder: distance_vs_angle, terminal_velocity_vs_fill, behaviour_map, speed_vs_time.\n"
        "A run folder (polyroll run --out) or a compare folder (polyroll compare --out): speed_vs_time,\n"
        "energy_vs_time and report.md (a row per run).\n"
        "Each figure as .png (.svg too with --format png,svg) beside a .csv of the numbers it plots.\n"
        "Examples:\n"
        "  polyroll figures sweeps/grid --out figures/\n"
        "  polyroll figures runs/cmp --out figures/cmp --format png,svg\n"
        "Runs shown against time whose trajectory the sweep did not keep (sweep --trajectories) are run again\n"
        "into OUT/runs/<id>/. Exit codes: 0 done, 2 bad input, 1 other failure (e.g. matplotlib missing).");
    sub.add_option("folder", a->folder, "sweep folder (plan.json, results.csv), run folder or compare folder")
        .required();
    sub.add_option("--out", a->out, "folder for the figures (default: figures)");
    sub.add_option("--format", a->format, "png, svg or png,svg (default: png)");
    sub.add_option("--runs", a->runs, "run ids for speed_vs_time.png, comma-separated (default: one run per "
                                      "behaviour)");
    sub.add_flag("--force", a->force, "write into an existing non-empty --out folder");
    return [a] { return run(*a); };
}

}  // namespace polyroll::cli
