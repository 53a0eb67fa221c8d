// polyroll sweep: a grid of scenes run in parallel into one results table; --plan-only, --from with
// --shard and --merge spread the same grid over hosts. See docs/sweeps.md.
#include <algorithm>
#include <map>
#include <optional>
#include <filesystem>
#include <thread>

#include <fmt/core.h>

#include "cli/commands.h"
#include "cli/interruptible_sweep.h"
#include "cli/scene_options.h"
#include "cli/slurm_submit.h"
#include "sim/errors.h"
#include "sim/message_text.h"
#include "sim/scene/scene_fields.h"
#include "sim/scene/scene_json.h"
#include "sweep/grid_request.h"
#include "sweep/grid_values.h"
#include "sweep/merge.h"
#include "sweep/progress.h"
#include "sweep/run_cost.h"
#include "sweep/sweep_plan.h"
#include "sweep/sweep_runner.h"

namespace polyroll::cli {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

std::string axis_help(const SceneField& f) {
    const bool listed = f.type == FieldType::preset || f.type == FieldType::choice;
    return field_help(f) + (listed ? "; one or a list" : "; a list or start:stop:step") + default_note(f);
}

struct SweepArgs {
    std::map<std::string, std::string> axis_text;  // flag -> its text
    std::vector<std::string> sets;                 // FIELD=VALUES
    std::string scene_file;
    std::string seed_list;
    int seeds = 0;
    std::string out, from, merge, shard;
    bool plan_only = false, trajectories = false, retry_failed = false, quiet = false, large = false;
    int jobs = 0;
    std::vector<Flag> scene_options;  // every option that defines the grid
};


sweep::SweepPlan plan_from_args(const SweepArgs& a, std::vector<std::string>& notes) {
    sweep::GridRequest request;
    if (!a.scene_file.empty()) {
        request.base = read_scene_file(a.scene_file).doc;
        request.base_origin = a.scene_file;
    }
    request.axis_text = a.axis_text;
    request.sets = a.sets;
    request.seed_list = a.seed_list;
    request.seeds = a.seeds;
    request.large = a.large;
    return sweep::make_request_plan(request, notes);
}

// The grid as planned, each axis with its values in run order, and the cost, before any run starts.
void print_grid(const sweep::SweepPlan& plan, const sweep::GridCheck& c, int jobs, const std::vector<std::string>& notes) {
    std::string axes;
    for (std::size_t i = 0; i < plan.fields.size(); ++i) {
        std::vector<std::string> values;
        for (const sweep::PlannedRun& run : plan.runs) {
            // A study's plan may set a field on some runs only (the cross-section sets closure.preset on
            // its closure column's): the others run the base scene's value.
            const std::string v =
                run.point.contains(plan.fields[i]) ? sweep::value_text(run.point.at(plan.fields[i])) : "(base)";
            if (std::find(values.begin(), values.end(), v) == values.end()) values.push_back(v);
        }
        std::string listed;
        for (std::size_t k = 0; k < values.size() && k < 8; ++k) listed += (k ? ", " : "") + values[k];
        if (values.size() > 8) listed += fmt::format(", ... ({} values)", values.size());
        axes += fmt::format("{}{} {}", axes.empty() ? "" : " x ", i < plan.flags.size() ? plan.flags[i] : plan.fields[i],
                            listed);
    }
    fmt::print("polyroll sweep: {} run{}: {}\n", plan.runs.size(), plan.runs.size() == 1 ? "" : "s",
               axes.empty() ? "the base scene only" : axes);
    for (const std::string& n : notes) fmt::print("  note: {}\n", n);
    if (c.invalid > 0)
        fmt::print("  note: {} of them cannot run and will be failed rows; the first: {}\n", c.invalid, c.first_invalid);
    fmt::print("  estimated at most {} with {} job{} (each run to its time limit; runs that stop sooner take less)\n",
               sweep::duration_text(c.max_cost_s / std::max(1, jobs)), jobs, jobs == 1 ? "" : "s");
    std::fflush(stdout);
}

void print_report(const sweep::SweepReport& r, int jobs) {
    const double per_min = r.wall_time_s > 0 ? 60.0 * static_cast<double>(r.ran) / r.wall_time_s : 0.0;
    fmt::print("polyroll sweep: {} of {} done in this session ({} failed), {} found done before; {} with {} "
               "job{} ({:.1f} runs/min)\n",
               r.ran, counted(static_cast<long long>(r.planned - r.already), "run"), r.failed, r.already,
               r.wall_time_s < 60 ? fmt::format("{:.1f} s", r.wall_time_s) : sweep::Progress::clock_text(r.wall_time_s),
               jobs,
               jobs == 1 ? "" : "s", per_min);
    fmt::print("  table  {}\n", r.table.string());
    if (r.failed > 0) fmt::print("  first failure  {}\n", r.first_failure);
    if (r.interrupted) fmt::print("  interrupted: run the same command again to resume\n");
}

int run_merge(const SweepArgs& a) {
    const sweep::SweepPlan plan = sweep::read_plan(a.merge);
    const sweep::MergeReport m = sweep::merge_tables(plan, a.merge);
    fmt::print("polyroll sweep --merge: {} tables, {} of {} runs ({} failed) into {}\n", m.tables, m.rows, m.runs,
               m.failed, (fs::path(a.merge) / "results.csv").string());
    if (m.missing.empty()) return kExitOk;
    std::string first;
    for (std::size_t i = 0; i < m.missing.size() && i < 10; ++i) first += (i ? ", " : "") + std::to_string(m.missing[i]);
    fmt::print(stderr, "polyroll sweep --merge: {} runs are in no table yet (plan indices {}{}); run the missing "
               "shards, or 'polyroll sweep --from {}' to run whatever is left\n",
               m.missing.size(), first, m.missing.size() > 10 ? ", ..." : "", a.merge);
    return kExitFailure;
}

int run(const SweepArgs& a, const SlurmFlags& slurm) {
    const int modes = !a.out.empty() + !a.from.empty() + !a.merge.empty();
    if (modes != 1)
        throw InputError("sweep: give exactly one of --out DIR (a new sweep or its resumption), --from DIR (run a "
                         "written plan) or --merge DIR");
    const bool grid_flags = std::any_of(a.scene_options.begin(), a.scene_options.end(),
                                        [](const Flag& o) { return o.count() > 0; });
    if (a.out.empty() && grid_flags)
        throw InputError(fmt::format("sweep: scene and grid flags are not allowed with --from or --merge (the plan "
                                     "in the folder defines the runs)"));
    if (!a.shard.empty() && a.from.empty())
        throw InputError("--shard needs --from DIR (write the plan first with --out DIR --plan-only)");
    if (a.plan_only && a.out.empty()) throw InputError("--plan-only needs --out DIR");
    if (slurm.asked() && !a.plan_only)
        throw InputError(fmt::format("--slurm-tasks {} needs --out DIR --plan-only (allowed: --slurm-tasks 1 to {} with "
                                     "--plan-only: the plan is written, and a job array runs it)",
                                     slurm.tasks, sweep::kMaxSlurmTasks));
    check_slurm_flags(slurm);
    std::optional<std::pair<int, int>> shard;
    if (!a.shard.empty()) shard = sweep::parse_shard(a.shard);  // flags before folders
    if (!a.merge.empty()) return run_merge(a);

    fs::path dir;
    sweep::SweepPlan plan;
    const int jobs = a.jobs > 0 ? a.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::string> notes;
    sweep::GridCheck check;
    if (!a.out.empty()) {
        dir = a.out;
        plan = plan_from_args(a, notes);
        // A point no run could use (--fill 25) is refused before anything is written, not found
        // after the sweep as a table of failed rows.
        check = sweep::check_grid(plan);
        sweep::refuse_unrunnable(plan, check, jobs, a.large);
        check_slurm_tasks_for_plan(slurm, plan.runs.size());
        sweep::open_sweep_folder(dir, "--out", plan, notes);
        print_grid(plan, check, jobs, notes);
        if (a.plan_only) {
            fmt::print("polyroll sweep: plan of {} written to {}\n", counted(static_cast<long long>(plan.runs.size()), "run"),
                       sweep::plan_path(dir).string());
            fmt::print("  run a slice:  polyroll sweep --from {} --shard K/N\n  then:        polyroll sweep --merge {}\n",
                       a.out, a.out);
            if (slurm.asked()) {
                const fs::path abs = fs::weakly_canonical(fs::absolute(dir));
                const std::string self = this_program();
                sweep::SlurmJob job{sweep::slurm_job_name("sweep", abs), abs, slurm.tasks, slurm.cpus_per_task,
                                    {self, "sweep", "--from", abs.string()}, {self, "sweep", "--merge", abs.string()}};
                std::fflush(stdout);
                return write_and_submit_slurm(job, slurm, "polyroll sweep");
            }
            return kExitOk;
        }
    } else {
        dir = a.from;
        plan = sweep::read_plan(dir);
        check = sweep::check_grid(plan);
        print_grid(plan, check, jobs, notes);
    }

    sweep::SweepOptions o;
    o.dir = dir;
    o.jobs = jobs;
    o.shard = shard;
    o.trajectories = a.trajectories;
    o.retry_failed = a.retry_failed;
    o.quiet = a.quiet;

    const sweep::SweepReport r = run_sweep_interruptibly(plan, o, "polyroll sweep");
    print_report(r, o.jobs);
    if (r.interrupted) return kExitInterrupted;
    if (r.ran > 0 && r.failed == r.ran) {
        fmt::print(stderr, "polyroll sweep: every run failed; the first: {}\n", printable_line(r.first_failure));
        return kExitFailure;
    }
    return kExitOk;
}

}  // namespace

Action add_sweep_command(Command& app) {
    auto a = std::make_shared<SweepArgs>();
    Command sub = app.add_subcommand("sweep", "run a grid of scenes in parallel into one results table");
    sub.footer(
        "Lists a,b,c and ranges start:stop:step (stop included) may be mixed: --fill 0,0.05:0.95:0.15,1.\n"
        "Examples:\n"
        "  polyroll sweep --sides 6,8 --fill 0:1:0.125 --angle 5:30:1 --material bb,rice,peas --seeds 3 --out sweeps/grid\n"
        "  polyroll sweep ... --out sweeps/big --plan-only     # write the plan, run nothing\n"
        "  polyroll sweep --from sweeps/big --shard 3/16      # one slice of it\n"
        "  polyroll sweep --merge sweeps/big                  # combine the slices into results.csv\n"
        "  polyroll sweep ... --out sweeps/big --plan-only --slurm-tasks 16   # and submit a Slurm job array running it\n"
        "Numbers listed out of order run in ascending order. Points that cannot run (--fill 25) are refused before\n"
        "anything is written. The same command resumes an interrupted sweep; with more values for the same flags it\n"
        "extends a sweep, keeping the runs done. Exit codes: 0 done (failed runs are\n"
        "rows of the table), 2 bad input, 130 interrupted (resume with the same command), 1 every run failed, another\n"
        "failure, or --merge with runs missing.");
    a->scene_options.push_back(
        sub.add_option("--scene", a->scene_file, "base scene file (JSON) under every point of the grid").group("Grid"));
    for (const SceneField* f : sweep::axis_fields()) {
        Flag o = sub.add_option_function(
                        std::string(f->flag),
                        [a, name = std::string(f->flag)](const std::string& v) { a->axis_text[name] = v; },
                        axis_help(*f))
                     .group("Grid");
        a->scene_options.push_back(o);
    }
    // One name (no --param alias: errors name --set, and calibrate's --params is another flag).
    a->scene_options.push_back(sub.add_option("--set", a->sets,
                                              "any scene field: FIELD=VALUES, e.g. --set shell.depth_m=0.05:0.07:0.01 "
                                              "(repeatable; fields as in a scene file, e.g. fill.material.diameter_m; "
                                              "null unsets an optional field)")
                                   .group("Grid"));
    a->scene_options.push_back(
        sub.add_option("--seed", a->seed_list, "a LIST of seeds for the grain packing, e.g. 1,5,9 "
                                               "(--seeds N is the count form: 1, 2, ..., N)").group("Grid"));
    a->scene_options.push_back(sub.add_option("--seeds", a->seeds, "a COUNT: N seeds per point, 1, 2, ..., N "
                                                                   "(--seed LIST names them instead)")
                                   .check(Range(1, 100000))
                                   .group("Grid"));
    sub.add_option("--out", a->out, "sweep folder: plan.json, results.csv, runs/<id>/; an existing sweep folder "
                                    "of the same command is resumed")
        .group("Folders");
    sub.add_flag("--plan-only", a->plan_only, "write the plan into --out and run nothing").group("Folders");
    sub.add_option("--from", a->from, "run the plan in this sweep folder (what is left of it)").group("Folders");
    sub.add_option("--shard", a->shard, "with --from: run slice K of N (runs whose index is K-1 modulo N)")
        .group("Folders");
    sub.add_option("--merge", a->merge, "combine the folder's tables into its results.csv").group("Folders");
    // 0 is refused like tradeoff's --jobs 0 (not read as "all cores": leaving the flag out says that).
    sub.add_option("--jobs,-j", a->jobs, "runs at a time, 1 to 1024 (default: all cores)")
        .check(Range(1, 1024))
        .group("Running");
    sub.add_flag("--trajectories", a->trajectories, "also write each run's trajectory.csv").group("Running");
    sub.add_flag("--retry-failed", a->retry_failed, "run again the runs recorded as failed").group("Running");
    sub.add_flag("--large", a->large, "confirm a plan of more than 100000 runs or 100 estimated hours (refused "
                                      "without it)")
        .group("Running");
    sub.add_flag("--quiet,-q", a->quiet, "no progress line").group("Running");
    auto slurm = std::make_shared<SlurmFlags>();
    add_slurm_flags(sub, slurm, "with --out DIR --plan-only");
    return [a, slurm] { return run(*a, *slurm); };
}

}  // namespace polyroll::cli
