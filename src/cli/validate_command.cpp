// polyroll validate: every observation of an observations file run over seeds on the sweep engine,
// then scored against the experiment (scorecard.csv, scorecard.json and a table on the terminal), and
// drawn (figures/: D against theta, the behaviour map) by src/figures/polyroll_figures.py.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numeric>
#include <thread>

#include <fmt/core.h>

#include "cli/commands.h"
#include "cli/interruptible_sweep.h"
#include "cli/observation_flags.h"
#include "cli/slurm_submit.h"
#include "figures/figures_script.h"
#include "sim/files/atomic_file.h"
#include "sim/errors.h"
#include "sim/message_text.h"
#include "sim/scene/scene_fields.h"
#include "sim/scene/scene_json.h"
#include "sweep/grid_values.h"
#include "sweep/observations.h"
#include "sweep/plan_extension.h"
#include "sweep/progress.h"
#include "sweep/results_table.h"
#include "sweep/run_cost.h"
#include "sweep/scorecard.h"
#include "sweep/sweep_runner.h"
#include "sweep/table_scoring.h"

namespace polyroll::cli {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;


struct ValidateArgs {
    std::string observations, out = "runs/validate", shard;
    std::vector<std::string> only;  // observation ids; empty: every observation of the file
    std::string half;               // one of the file's named halves (its "halves"); empty: all
    int seeds = 5, jobs = 0;
    bool force = false, quiet = false;
    ObservationSceneFlags scene;  // on top of every observation
};


// The folder's validation files, removed by --force when the folder holds another validation.
void remove_old_validation(const fs::path& dir) {
    for (const char* name : {"plan.json", "results.csv", "shards", "runs", "scorecard.csv", "scorecard.json",
                             "observations.json", "figures"})
        fs::remove_all(dir / name);
}

// The figures of a scored folder, into DIR/figures/. Figures are an extra: without a Python that has
// matplotlib the command says so and what to install, and the scorecard stands (exit 0); a figure
// script that fails is a fault worth an exit code (1), the scorecard still written.
int draw_figures(const fs::path& dir) {
    try {
        figures::figures_python();
        figures::figures_script();
    } catch (const std::runtime_error& e) {
        fmt::print(stderr, "polyroll validate: no figures drawn: {}; the scorecard is written\n", e.what());
        return kExitOk;
    }
    const fs::path out = dir / "figures";
    fs::create_directories(out);
    std::fflush(stdout);  // the script's lines (one per file written) come after ours
    const int code = figures::run_figures_script(
        {"validate", (dir / "scorecard.json").string(), (dir / "results.csv").string(), out.string()});
    if (code == 0) return kExitOk;
    fmt::print(stderr, "polyroll validate: the figure script failed (exit code {}); the scorecard is written\n", code);
    return kExitFailure;
}

// The plan before any run starts, as polyroll sweep prints its grid: each observation's runs, the
// seeds, and at most how long the runs this session will do take, so that a validation of many
// minutes says so before it starts rather than in its progress line.
void print_plan(const sweep::ObservationFile& file, const sweep::ValidationPlan& vp, int seeds,
                const std::vector<std::size_t>& todo, std::size_t in_session, int jobs) {
    fmt::print("polyroll validate: {} observation{} of {}, {} run{} ({} seed{} each)\n", file.observations.size(),
               file.observations.size() == 1 ? "" : "s", file.origin, vp.plan.runs.size(),
               vp.plan.runs.size() == 1 ? "" : "s", seeds, seeds == 1 ? "" : "s");
    std::vector<std::size_t> runs(file.observations.size(), 0);
    for (const sweep::RunPlace& p : vp.places) ++runs[p.observation];
    std::size_t width = 0;
    for (const sweep::Observation& ob : file.observations) width = std::max(width, ob.id.size());
    for (std::size_t i = 0; i < file.observations.size(); ++i)
        fmt::print("  {:<{}}  {:>5} run{} ({} scene{} x {} seed{})\n", file.observations[i].id, width, runs[i],
                   runs[i] == 1 ? " " : "s", runs[i] / static_cast<std::size_t>(seeds),
                   runs[i] / static_cast<std::size_t>(seeds) == 1 ? "" : "s", seeds, seeds == 1 ? "" : "s");
    if (vp.places.size() > vp.plan.runs.size())
        fmt::print("  note: {} of these runs {} shared by two observations and run{} once\n",
                   vp.places.size() - vp.plan.runs.size(), vp.places.size() - vp.plan.runs.size() == 1 ? "is" : "are",
                   vp.places.size() - vp.plan.runs.size() == 1 ? "s" : "");
    if (todo.size() < in_session)
        fmt::print("  note: {} of {} runs found done before; {} left\n", in_session - todo.size(), in_session,
                   todo.size());
    double cost_s = 0.0;
    for (std::size_t i : todo) cost_s += sweep::max_run_seconds(vp.plan, vp.plan.runs[i]);
    if (!todo.empty())
        fmt::print("  estimated at most {} with {} job{} (each run to its time limit; runs that stop sooner take "
                   "less)\n",
                   sweep::duration_text(cost_s / std::max(1, std::min<int>(jobs, static_cast<int>(todo.size())))),
                   jobs, jobs == 1 ? "" : "s");
    std::fflush(stdout);
}

// --slurm-tasks N: the folder's plan as a job array whose task K runs this command with --shard K/N,
// then the same command without --shard, which scores (see cli/slurm_submit.h).
int submit_slurm(const ValidateArgs& a, const SlurmFlags& slurm, const fs::path& dir) {
    const fs::path abs = fs::weakly_canonical(fs::absolute(dir));
    std::vector<std::string> argv = {this_program(), "validate"};
    if (!a.observations.empty()) argv.insert(argv.end(), {"--observations", fs::absolute(a.observations).string()});
    if (!a.only.empty()) {
        std::string only;
        for (const std::string& id : a.only) only += (only.empty() ? "" : ",") + id;
        argv.insert(argv.end(), {"--only", only});
    }
    if (!a.half.empty()) argv.insert(argv.end(), {"--half", a.half});
    argv.insert(argv.end(), {"--seeds", std::to_string(a.seeds)});
    for (const std::string& w : observation_flags_args(a.scene)) argv.push_back(w);
    argv.insert(argv.end(), {"--out", abs.string()});
    std::vector<std::string> finish = argv;
    finish.insert(finish.end(), {"--jobs", "1", "--quiet"});
    sweep::SlurmJob job{sweep::slurm_job_name("validate", abs), abs, slurm.tasks, slurm.cpus_per_task, argv, finish,
                        "score"};
    std::fflush(stdout);
    return write_and_submit_slurm(job, slurm, "polyroll validate");
}

int run(const ValidateArgs& a, const SlurmFlags& slurm) {
    std::optional<std::pair<int, int>> shard;
    if (!a.shard.empty()) shard = sweep::parse_shard(a.shard);
    if (slurm.asked() && shard)
        throw InputError(fmt::format("--slurm-tasks {} and --shard {} are both given (allowed: one: --slurm-tasks N "
                                     "writes and submits all N slices, --shard K/N runs one)",
                                     slurm.tasks, a.shard));
    check_slurm_flags(slurm);
    sweep::ObservationFile file = sweep::read_observations(a.observations);
    if (!a.half.empty()) file = sweep::half_of(file, a.half);
    if (!a.only.empty()) file = sweep::only_observations(file, a.only, "--only");
    const sweep::ValidationPlan vp = sweep::make_validation_plan(file, a.seeds, observation_overrides(a.scene));
    check_slurm_tasks_for_plan(slurm, vp.plan.runs.size());

    const fs::path dir = a.out;
    std::error_code ec;
    bool fresh = true;
    if (fs::exists(sweep::plan_path(dir), ec)) {
        // Resuming: the folder's plan must be this command's (or --force starts over).
        const sweep::SweepPlan existing = sweep::read_plan(dir);
        const std::string refusal = sweep::extension_refusal(existing, vp.plan);
        if (sweep::plan_to_json(existing) == sweep::plan_to_json(vp.plan)) {
            fresh = false;
        } else if (a.force) {
            remove_old_validation(dir);  // its tables and runs are of another plan: never mixed with this one's
        } else if (refusal.empty()) {
            // More seeds (or more observations) for the same scenes: the runs done are kept, by id.
            sweep::extend_plan(dir, vp.plan);
            fresh = false;
            fmt::print("polyroll validate: extends the validation in {}: {} runs were planned there, {} now\n", a.out,
                       existing.runs.size(), vp.plan.runs.size());
        } else {
            throw InputError(fmt::format("--out {}: holds a different validation (its plan.json has {} runs, this "
                                         "command {}: {}); allowed: --out with a new folder, the same command to "
                                         "resume, more seeds or observations to extend it, or --force to start over",
                                         a.out, existing.runs.size(), vp.plan.runs.size(), refusal));
        }
    }
    if (fresh) {
        prepare_output_dir(dir, a.force);
        sweep::write_plan(dir, vp.plan);
    }
    // The observations as read: what the scorecard in this folder was scored against.
    write_file_atomic(dir / "observations.json", file.doc.dump(2) + "\n");

    sweep::SweepOptions o;
    o.dir = dir;
    o.jobs = a.jobs > 0 ? a.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    o.shard = shard;
    o.quiet = a.quiet;
    {
        // The runs this session will do: the shard's, less those a resumed folder holds.
        std::vector<std::size_t> slice(vp.plan.runs.size());
        std::iota(slice.begin(), slice.end(), std::size_t{0});
        if (shard) slice = sweep::shard_indices(vp.plan.runs.size(), shard->first, shard->second);
        const std::map<std::size_t, sweep::ScoredRun> done =
            fresh ? std::map<std::size_t, sweep::ScoredRun>() : sweep::finished_outcomes(vp.plan, dir);
        std::vector<std::size_t> todo;
        for (std::size_t i : slice)
            if (!done.count(i)) todo.push_back(i);
        print_plan(file, vp, a.seeds, todo, slice.size(), o.jobs);
    }
    if (slurm.asked()) return submit_slurm(a, slurm, dir);
    const sweep::SweepReport r = run_sweep_interruptibly(vp.plan, o, "polyroll validate");
    fmt::print("polyroll validate: {}, {} ({} each): {} run now ({} failed), {} found done before, {}\n",
               counted(static_cast<long long>(file.observations.size()), "observation"),
               counted(static_cast<long long>(vp.plan.runs.size()), "run"), counted(a.seeds, "seed"), r.ran, r.failed,
               r.already,
               r.wall_time_s < 60 ? fmt::format("{:.1f} s", r.wall_time_s) : sweep::Progress::clock_text(r.wall_time_s));
    if (r.interrupted) {
        fmt::print("  interrupted: run the same command again to resume\n");
        return kExitInterrupted;
    }
    if (shard) {
        fmt::print("  shard {}/{} done; when every shard is, run the same command without --shard to score\n",
                   shard->first, shard->second);
        return kExitOk;
    }
    const std::vector<sweep::ObservationScore> scores =
        sweep::score_validation(file, vp, sweep::finished_outcomes(vp.plan, dir));
    const json about = {{"observations_file", file.origin}, {"seeds", a.seeds}, {"runs", vp.plan.runs.size()},
                        {"overrides", [&] {
                             json o2 = json::object();
                             for (const auto& [f, v] : observation_overrides(a.scene)) o2[f] = v;
                             return o2;
                         }()}};
    write_file_atomic(dir / "scorecard.csv", sweep::scorecard_csv(scores));
    write_file_atomic(dir / "scorecard.json", sweep::scorecard_json(scores, about).dump(1) + "\n");
    fmt::print("\n{}", sweep::scorecard_text(scores));
    fmt::print("  scorecard  {}  {}\n", (dir / "scorecard.csv").string(), (dir / "scorecard.json").string());
    return draw_figures(dir);
}

}  // namespace

Action add_validate_command(Command& app) {
    auto a = std::make_shared<ValidateArgs>();
    Command sub = app.add_subcommand("validate", "run the experiment's observations over seeds and score the "
                                                 "simulation against them");
    sub.footer(
        "Observations: assets/experiment.json (bundled) or --observations FILE of the same form (its \"format\"\n"
        "block describes every key). Scene flags apply on top of every observation.\n"
        "Examples:\n"
        "  polyroll validate --seeds 3 --out runs/validate\n"
        "  polyroll validate --observations my-lab.json --fidelity draft --jobs 2\n"
        "  polyroll validate --only fig7-hexagon-rolls --seeds 2   # one observation of the file\n"
        "  polyroll validate ... --shard 2/4    # one slice; then the same command without --shard scores\n"
        "  polyroll validate ... --slurm-tasks 4   # a Slurm job array of the 4 slices, then a job that scores\n"
        "Figures (D against theta, the behaviour map; PNG, SVG and CSV) go to OUT/figures/ when python3-matplotlib\n"
        "is installed; without it the scorecard is still written.\n"
        "The same command resumes; with more seeds it extends the folder, keeping the runs done. Exit codes:\n"
        "0 ran (agreement or not is in the scorecard), 2 bad input,\n"
        "130 interrupted (resume with the same command), 1 other failure.");
    sub.add_option("--observations", a->observations, "observations file (JSON; default: the bundled experiment.json)");
    sub.add_option("--only", a->only, "run only the observation with this id (repeat the flag or give a list a,b; "
                                      "default: every observation of the file)")
        .delimiter(',');
    sub.add_option("--half", a->half, "run only the observations of this half of the file (its \"halves\", e.g. "
                                      "fit or held_back in assets/reference-3d.json)");
    sub.add_option("--seeds", a->seeds, "seeds per scene: 1, 2, ..., N (default 5)").check(Range(1, 1000));
    sub.add_option("--out", a->out, "folder: plan.json, results.csv, runs/<id>/, scorecard.csv, scorecard.json, "
                                    "figures/ (default runs/validate); the same command there resumes, more seeds extend it");
    // 0 is refused as sweep's and tradeoff's --jobs 0 are (leaving the flag out means all cores).
    sub.add_option("--jobs,-j", a->jobs, "runs at a time, 1 to 1024 (default: all cores)")
        .check(Range(1, 1024))
        .group("Running");
    sub.add_option("--shard", a->shard, "run slice K of N only (runs whose index is K-1 modulo N)").group("Running");
    sub.add_flag("--force", a->force, "start over in a folder holding something else (its validation files are "
                                      "replaced)").group("Running");
    sub.add_flag("--quiet,-q", a->quiet, "no progress line").group("Running");
    add_observation_scene_flags(sub, std::shared_ptr<ObservationSceneFlags>(a, &a->scene));
    auto slurm = std::make_shared<SlurmFlags>();
    add_slurm_flags(sub, slurm, "run nothing here (the plan is written)");
    return [a, slurm] { return run(*a, *slurm); };
}

}  // namespace polyroll::cli
