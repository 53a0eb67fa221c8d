// polyroll calibrate: fits chosen unmeasured scene fields to an observations file.
// The optimiser, the objective and the folder's growing plan are in sweep/calibration.*; this file
// checks the command line, keeps the output folder (resume, --force) and writes the results.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <thread>

#include <fmt/core.h>

#include "cli/commands.h"
#include "cli/interruptible_sweep.h"
#include "cli/observation_flags.h"
#include "sim/message_text.h"
#include "sim/files/atomic_file.h"
#include "sim/errors.h"
#include "sim/scene/json_path.h"
#include "sim/scene/scene_json.h"
#include "sweep/calibration.h"
#include "sweep/grid_values.h"
#include "sweep/progress.h"
#include "sweep/results_table.h"
#include "sweep/run_cost.h"
#include "sweep/scorecard.h"

namespace polyroll::cli {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

constexpr int kMaxEvaluations = 10000;
// --first-pass-grains: the trade study measured discs 1.5 and 2 times larger (docs/tradeoff/); past
// 3 a small shell holds too few discs for a pile.
constexpr double kMaxFirstPassGrainScale = 3.0;

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

struct CalibrateArgs {
    std::string params, observations, half, out = "runs/calibrate", algorithm = "sbplx", shard;
    std::vector<std::string> starts;  // FIELD=VALUE
    std::vector<std::string> only;    // observation ids (after --half); empty: every observation
    int seeds = 2, jobs = 0, max_evals = 24;  // measured at standard: docs/calibrate.md
    int first_pass_seeds = 0;                 // 0: no first pass
    double first_pass_grains = 1.0;           // 1: the first pass's grains are the scene's
    bool force = false, quiet = false, plan_only = false;
    ObservationSceneFlags scene;
};

// The command as given, for the provenance (rebuilt from the parsed values: the same command).
std::string command_text(const CalibrateArgs& a) {
    std::string c = "polyroll calibrate --params " + a.params;
    if (!a.observations.empty()) c += " --observations " + a.observations;
    if (!a.half.empty()) c += " --half " + a.half;
    if (!a.only.empty()) {
        c += " --only ";
        for (std::size_t i = 0; i < a.only.size(); ++i) c += (i ? "," : "") + a.only[i];
    }
    c += fmt::format(" --seeds {} --max-evals {} --algorithm {}", a.seeds, a.max_evals, a.algorithm);
    if (a.first_pass_seeds > 0) c += fmt::format(" --first-pass-seeds {}", a.first_pass_seeds);
    if (a.first_pass_grains != 1.0) c += fmt::format(" --first-pass-grains {:g}", a.first_pass_grains);
    for (const std::string& s : a.starts) c += " --start " + s;
    if (!a.shard.empty()) c += " --shard " + a.shard;
    c += observation_flags_text(a.scene);
    c += " --out " + a.out;
    return c;
}

std::vector<std::pair<std::string, double>> starts_of(const CalibrateArgs& a) {
    std::vector<std::pair<std::string, double>> out;
    for (const std::string& s : a.starts) {
        const auto eq = s.find('=');
        std::vector<json> v;
        if (eq != std::string::npos && eq > 0) v = sweep::parse_grid_values("--start " + s.substr(0, eq), s.substr(eq + 1));
        if (v.size() != 1 || !v.front().is_number())
            throw InputError(fmt::format("--start '{}' is not FIELD=NUMBER (e.g. --start ramp.friction=0.6)", s));
        out.emplace_back(s.substr(0, eq), v.front().get<double>());
    }
    return out;
}

// Everything that decides the calibration's path: a folder whose calibration.json has the same
// setup is resumed. The budget is not part of it: rerunning with a larger --max-evals continues.
json setup_json(const sweep::CalibrationSetup& s) {
    json params = json::array();
    for (const sweep::CalibrationParam& p : s.params)
        params.push_back(json{{"field", p.path}, {"from", p.lo}, {"to", p.hi}, {"bounds_from", p.bounds_from},
                              {"start", p.start}, {"start_from", p.start_from}});
    json overrides = json::object();
    for (const auto& [f, v] : s.overrides) overrides[f] = v;
    json doc{{"observations_file", s.file.origin}, {"observations", s.file.doc}, {"seeds", s.seeds},
             {"overrides", overrides}, {"params", params}, {"algorithm", s.algorithm}};
    // Only when asked for, so that a folder of a calibration without one resumes as before.
    if (s.first_pass_seeds > 0) doc["first_pass_seeds"] = s.first_pass_seeds;
    if (s.first_pass_grain_scale != 1.0) doc["first_pass_grain_scale"] = s.first_pass_grain_scale;
    return doc;
}

const std::vector<const char*> kCalibrationFiles = {"plan.json", "results.csv", "shards", "runs", "evaluations.csv",
                                                    "calibration.json", "calibrated-scene.json", "observations.json",
                                                    "scorecard.csv", "scorecard.json"};

std::string values_text(const sweep::CalibrationSetup& s, const std::vector<double>& v) {
    std::string out;
    for (std::size_t i = 0; i < v.size(); ++i) out += fmt::format("{}{}={:.6g}", i ? " " : "", s.params[i].path, v[i]);
    return out;
}

std::string evaluations_csv(const sweep::CalibrationSetup& s, const std::vector<sweep::Evaluation>& evals) {
    std::vector<std::string> header = {"evaluation"};
    for (const auto& p : s.params) header.push_back(p.path);
    for (const char* c : {"objective", "checks_agreeing", "checks", "seeds", "grain_scale", "runs", "failed", "ran",
                          "wall_time_s"})
        header.emplace_back(c);
    std::string out = sweep::csv_line(header);
    for (const sweep::Evaluation& e : evals) {
        std::vector<std::string> row = {std::to_string(e.number)};
        for (double v : e.values) row.push_back(sweep::number_cell(v));
        row.push_back(sweep::number_cell(e.objective));
        for (std::size_t n : {e.agreeing, e.checks, static_cast<std::size_t>(e.seeds)})
            row.push_back(std::to_string(n));
        row.push_back(sweep::number_cell(e.grain_scale));
        for (std::size_t n : {e.runs, e.failed, e.ran}) row.push_back(std::to_string(n));
        row.push_back(fmt::format("{:.3f}", e.wall_time_s));
        out += sweep::csv_line(row);
    }
    return out;
}

// The calibrated values (and the command line's) as a partial scene file, with its provenance in the
// scene file's free-text "description".
json calibrated_scene(const sweep::CalibrationSetup& s, const sweep::Evaluation& best, const sweep::Evaluation& before,
                      const std::string& command) {
    json doc = json::object();
    doc["description"] = fmt::format(
        "Calibrated by polyroll calibrate: {} fitted to {} ({} observations, seeds 1..{}); objective {:.4g} with the "
        "scene's own values, {:.4g} with these ({} of {} checks agree, {} before). Command: {}. Details: "
        "calibration.json beside this file.",
        values_text(s, best.values), s.file.origin, s.file.observations.size(), s.seeds, before.objective,
        best.objective, best.agreeing, best.checks, before.agreeing, command);
    for (const auto& [f, v] : s.overrides) node_at(doc, f) = v;
    for (std::size_t i = 0; i < s.params.size(); ++i) node_at(doc, s.params[i].path) = best.values[i];
    return doc;
}

json evaluation_json(const sweep::CalibrationSetup& s, const sweep::Evaluation& e) {
    json values = json::object();
    for (std::size_t i = 0; i < e.values.size(); ++i) values[s.params[i].path] = e.values[i];
    return json{{"evaluation", e.number}, {"values", values}, {"objective", e.objective},
                {"checks_agreeing", e.agreeing}, {"checks", e.checks}, {"seeds", e.seeds},
                {"grain_scale", e.grain_scale}, {"runs", e.runs},
                {"failed", e.failed}};
}

// --max-evals and --algorithm, checked before anything is read.
void check_search_flags(const CalibrateArgs& a) {
    if (a.max_evals < 0 || a.max_evals > kMaxEvaluations)
        throw InputError(fmt::format("--max-evals {} is out of range (allowed: 0 to {})", a.max_evals, kMaxEvaluations));
    const auto& algorithms = sweep::calibration_algorithms();
    if (std::find(algorithms.begin(), algorithms.end(), a.algorithm) == algorithms.end())
        throw InputError(fmt::format("--algorithm {}: unknown (allowed: sbplx, bobyqa, cobyla, neldermead)", a.algorithm));
}

// The calibration the flags ask for: observations, fields with their bounds and starts, every corner
// of the bounds checked as a scene of every observation before anything is written.
sweep::CalibrationSetup setup_of(const CalibrateArgs& a) {
    sweep::CalibrationSetup setup;
    setup.file = sweep::read_observations(a.observations);
    if (!a.half.empty()) setup.file = sweep::half_of(setup.file, a.half);
    if (!a.only.empty()) setup.file = sweep::only_observations(setup.file, a.only, "--only");
    setup.seeds = a.seeds;
    if (a.first_pass_seeds < 0 || a.first_pass_seeds >= a.seeds)
        if (a.first_pass_seeds != 0)
            throw InputError(fmt::format("--first-pass-seeds {}: allowed 1 to --seeds - 1 ({}), or 0 for no first pass",
                                         a.first_pass_seeds, a.seeds - 1));
    setup.first_pass_seeds = a.first_pass_seeds;
    if (!(a.first_pass_grains >= 1.0 && a.first_pass_grains <= kMaxFirstPassGrainScale))
        throw InputError(fmt::format("--first-pass-grains {:g}: allowed 1 (the scene's grains) to {:g}",
                                     a.first_pass_grains, kMaxFirstPassGrainScale));
    setup.first_pass_grain_scale = a.first_pass_grains;
    setup.overrides = observation_overrides(a.scene);
    setup.algorithm = a.algorithm;
    setup.max_evaluations = a.max_evals;
    // The scene the fields' limits and own values are read from: the observations' first run.
    const sweep::ValidationPlan first = sweep::make_validation_plan(setup.file, 1, setup.overrides);
    const Scene scene = resolve_scene(sweep::run_layers(first.plan, first.plan.runs.front()));
    setup.params = sweep::parse_calibration_params(a.params, scene, setup.file);
    for (const auto& p : setup.params)
        for (const auto& [f, v] : setup.overrides)
            if (f == p.path)
                throw InputError(fmt::format("--params {}: also set on the command line (allowed: fit it or set it, "
                                             "not both; --start {}=VALUE starts the search there)", f, f));
    sweep::set_start_values(setup.params, scene, starts_of(a));
    // Both corners of the bounds must be valid scenes for every observation, with both passes' grains:
    // checked before anything is written.
    for (const bool upper : {false, true}) {
        std::vector<double> corner;
        for (const auto& p : setup.params) corner.push_back(upper ? p.hi : p.lo);
        for (const double scale : {1.0, setup.search_grain_scale()}) sweep::candidate_plan(setup, corner, 1, scale);
    }
    return setup;
}

// The output folder made ready: resumed when it holds this calibration, refused when it holds another
// (unless --force), and the calibration's first files written.
void start_folder(const CalibrateArgs& a, const sweep::CalibrationSetup& setup, const json& setup_doc, bool sharded,
                  const std::string& command) {
    const fs::path dir = a.out;
    std::error_code ec;
    bool resume = false;
    if (fs::exists(dir / "calibration.json", ec)) {
        json old;
        try {
            old = json::parse(read_text(dir / "calibration.json"));
        } catch (const std::exception&) {
        }
        if (old.is_object() && old.value("setup", json()) == setup_doc)
            resume = true;
        else if (!a.force)
            throw InputError(fmt::format("--out {}: holds another calibration (other observations, fields, bounds, "
                                         "seeds or scene flags); allowed: a new folder, the same command to resume, or "
                                         "--force to start over", a.out));
        else
            for (const char* name : kCalibrationFiles) fs::remove_all(dir / name);
    }
    // The shards of one calibration start side by side: a folder holding another shard's first files is theirs.
    if (!resume) prepare_output_dir(dir, a.force || sharded);
    write_file_atomic(dir / "observations.json", setup.file.doc.dump(2) + "\n");
    write_file_atomic(dir / "calibration.json",
                      json{{"format", "polyroll-calibration-1"}, {"status", "running"}, {"command", command},
                           {"setup", setup_doc}}
                              .dump(1) + "\n");
}

// calibration.json done, the calibrated scene and the best evaluation's scorecard.
void write_outcome(const fs::path& dir, const sweep::CalibrationSetup& setup, const json& setup_doc,
                   const sweep::CalibrationOutcome& outcome, const std::string& command) {
    const sweep::Evaluation& before = outcome.evaluations.front();
    const sweep::Evaluation& best = outcome.evaluations[outcome.best];
    json params = json::array();
    for (std::size_t i = 0; i < setup.params.size(); ++i) {
        const auto& p = setup.params[i];
        params.push_back(json{{"field", p.path}, {"from", p.lo}, {"to", p.hi}, {"bounds_from", p.bounds_from},
                              {"start", p.start}, {"start_from", p.start_from}, {"best", best.values[i]}});
    }
    json evaluations = json::array();
    for (const auto& e : outcome.evaluations) evaluations.push_back(evaluation_json(setup, e));
    const json doc = {{"format", "polyroll-calibration-1"},
                      {"status", "done"},
                      {"command", command},
                      {"setup", setup_doc},
                      {"params", params},
                      {"objective", "sum over every check of its miss squared, in tolerances (docs/calibrate.md)"},
                      {"objective_before", before.objective},
                      {"objective_after", best.objective},
                      {"checks_agreeing_before", before.agreeing},
                      {"checks_agreeing_after", best.agreeing},
                      {"checks", best.checks},
                      {"best_evaluation", best.number},
                      {"evaluations_run", outcome.evaluations.size()},
                      {"stop_reason", outcome.stop_reason},
                      {"evaluations", evaluations}};
    write_file_atomic(dir / "calibration.json", doc.dump(1) + "\n");
    write_file_atomic(dir / "calibrated-scene.json", calibrated_scene(setup, best, before, command).dump(2) + "\n");
    const json about = {{"observations_file", setup.file.origin}, {"seeds", setup.seeds},
                        {"calibrated", evaluation_json(setup, best)["values"]}};
    write_file_atomic(dir / "scorecard.csv", sweep::scorecard_csv(best.scores));
    write_file_atomic(dir / "scorecard.json", sweep::scorecard_json(best.scores, about).dump(1) + "\n");
}

// The closing summary on stdout: the fitted values, the objective before and after, where the files are.
void print_outcome(const fs::path& dir, const sweep::CalibrationSetup& setup, const sweep::CalibrationOutcome& outcome,
                   std::size_t runs_in_folder) {
    const sweep::Evaluation& before = outcome.evaluations.front();
    const sweep::Evaluation& best = outcome.evaluations[outcome.best];
    fmt::print("polyroll calibrate: {} ({}), {} in the folder\n",
               counted(static_cast<long long>(outcome.evaluations.size()), "evaluation"), outcome.stop_reason,
               counted(static_cast<long long>(runs_in_folder), "run"));
    for (std::size_t i = 0; i < setup.params.size(); ++i)
        fmt::print("  {:<32} {:.6g} (start {:.6g}, bounds {:g} to {:g})\n", setup.params[i].path, best.values[i],
                   setup.params[i].start, setup.params[i].lo, setup.params[i].hi);
    fmt::print("  objective          {:.4g} before, {:.4g} after (#{}); checks agreeing {} before, {} after, of {}\n",
               before.objective, best.objective, best.number, before.agreeing, best.agreeing, best.checks);
    fmt::print("  calibrated scene   {}\n", (dir / "calibrated-scene.json").string());
    fmt::print("  details            {}  {}  {}\n", (dir / "calibration.json").string(),
               (dir / "evaluations.csv").string(), (dir / "scorecard.csv").string());
}

// The plan before the first evaluation, as validate prints its own: what is fitted, how many runs a
// candidate takes and at most how long, so that a calibration of an hour says so before it starts.
void print_plan(const sweep::CalibrationSetup& setup, int jobs) {
    auto at_start = setup.overrides;
    for (const auto& p : setup.params) at_start.emplace_back(p.path, p.start);
    const sweep::ValidationPlan vp = sweep::make_validation_plan(setup.file, setup.seeds, at_start, true);
    fmt::print("polyroll calibrate: {} field{} against {} observation{} of {}, {} seed{} a scene\n", setup.params.size(),
               setup.params.size() == 1 ? "" : "s", setup.file.observations.size(),
               setup.file.observations.size() == 1 ? "" : "s", setup.file.origin, setup.seeds,
               setup.seeds == 1 ? "" : "s");
    for (const auto& p : setup.params)
        fmt::print("  {:<32} from {:g} to {:g}, start {:.6g} ({})\n", p.path, p.lo, p.hi, p.start, p.start_from);
    double cost_s = 0.0;
    for (const sweep::PlannedRun& r : vp.plan.runs) cost_s += sweep::max_run_seconds(vp.plan, r);
    const double candidate_s = cost_s / std::max(1, std::min<int>(jobs, static_cast<int>(vp.plan.runs.size())));
    const int candidates = setup.max_evaluations + 1;
    fmt::print("  {} a candidate; {} at most (the scene's own values, then --max-evals {})\n",
               counted(static_cast<long long>(vp.plan.runs.size()), "run"), counted(candidates, "candidate"),
               setup.max_evaluations);
    fmt::print("  estimated at most {} a candidate and {} in all with {} job{} (each run to its time limit; runs "
               "that stop sooner take less)\n",
               sweep::duration_text(candidate_s), sweep::duration_text(candidate_s * candidates), jobs,
               jobs == 1 ? "" : "s");
    std::fflush(stdout);
}

int run(const CalibrateArgs& a) {
    check_search_flags(a);
    std::optional<std::pair<int, int>> shard;
    if (!a.shard.empty()) shard = sweep::parse_shard(a.shard);
    const sweep::CalibrationSetup setup = setup_of(a);
    const fs::path dir = a.out;
    const json setup_doc = setup_json(setup);
    const std::string command = command_text(a);
    const int jobs = a.jobs > 0 ? a.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    if (!a.quiet || a.plan_only) print_plan(setup, jobs);
    if (a.plan_only) return kExitOk;  // nothing written: the folder's plan grows with the search
    start_folder(a, setup, setup_doc, shard.has_value(), command);

    // Ctrl-C at any moment, during a candidate's sweep or between two, stops at the next sweep.
    const InterruptScope interrupt_scope("polyroll calibrate");
    sweep::CalibrationRuns runs(dir, setup, [&](const sweep::SweepPlan& plan, const std::vector<double>& expected_s) {
        sweep::SweepOptions o;
        o.expected_s = expected_s;
        o.dir = dir;
        o.jobs = jobs;
        o.quiet = true;  // one line per evaluation instead
        o.shard = shard;
        return run_sweep_interruptibly(plan, o, "polyroll calibrate");
    }, shard.has_value(), [&](std::size_t missing) {
        if (!a.quiet)
            fmt::print(stderr, "polyroll calibrate: shard {}/{} done with this candidate; waiting for the other "
                               "shards' {} runs\n", shard->first, shard->second, missing);
    }, [&] { return interrupt_scope.interrupted(); });
    std::vector<sweep::Evaluation> seen;
    const std::size_t budget = static_cast<std::size_t>(a.max_evals) + 1;
    auto progress = [&](const sweep::Evaluation& e, const sweep::Evaluation& best) {
        seen.push_back(e);
        write_file_atomic(dir / "evaluations.csv", evaluations_csv(setup, seen));
        if (a.quiet) return;
        // In one bracket: what the candidate is, and with a first pass, what its runs were.
        std::string what = e.number == 0 ? "the scene's own values" : "";
        if (setup.has_first_pass()) {
            const std::string grains = e.grain_scale == 1.0 ? "" : fmt::format(", grains x{:g}", e.grain_scale);
            what += (what.empty() ? "" : ", ") +
                    (e.number >= budget ? fmt::format("final pass, {} seeds", e.seeds)
                                        : fmt::format("{} seed{}{}", e.seeds, e.seeds == 1 ? "" : "s", grains));
        }
        if (!what.empty()) what = " (" + what + ")";
        fmt::print(stderr, "polyroll calibrate: evaluation {}/{}{} {}: objective {:.4g} ({} of {} checks agree, {} runs{}, "
                           "{}); best {:.4g} (#{})\n",
                   e.number, budget - 1, what, values_text(setup, e.values),
                   e.objective, e.agreeing, e.checks, e.runs,
                   e.failed ? fmt::format(", {} failed", e.failed) : std::string(),
                   e.ran == 0 ? "found done" : fmt::format("{:.1f} s", e.wall_time_s), best.objective, best.number);
    };
    sweep::CalibrationOutcome outcome;
    try {
        outcome = sweep::run_calibration(setup, runs, progress);
    } catch (const sweep::CalibrationInterrupted&) {
        fmt::print("polyroll calibrate: interrupted after {} evaluations: run the same command again to resume\n",
                   seen.size());
        return kExitInterrupted;
    }
    write_outcome(dir, setup, setup_doc, outcome, command);
    print_outcome(dir, setup, outcome, runs.plan().runs.size());
    return kExitOk;
}

}  // namespace

Action add_calibrate_command(Command& app) {
    auto a = std::make_shared<CalibrateArgs>();
    Command sub = app.add_subcommand("calibrate", "fit unmeasured scene fields to an observations file");
    sub.footer(
        "Each candidate runs every observation over seeds 1..N (the same seeds for every candidate) as rows of\n"
        "one sweep folder; NLopt minimises the scorecard's summed squared misses within the bounds. Bounds:\n"
        "FIELD=FROM:TO, else assets/calibration.json's, else the field's limits. docs/calibrate.md.\n"
        "Examples:\n"
        "  polyroll calibrate --params fill.material.restitution,fill.material.friction,ramp.friction --jobs 2\n"
        "  polyroll calibrate --params ramp.friction=0.4:1.0 --observations my-lab.json --fidelity draft\n"
        "  polyroll calibrate --params ramp.friction --plan-only   # the plan and its time, nothing run\n"
        "The same command resumes (a larger --max-evals continues). Exit codes: 0 done, 2 bad input,\n"
        "130 interrupted (resume with the same command), 1 other failure.");
    sub.add_option("--params", a->params, "fields to fit: FIELD[=FROM:TO],... (scene-file paths, numbers)").required();
    sub.add_option("--observations", a->observations, "observations file (JSON; default: the bundled experiment.json)");
    sub.add_option("--half", a->half, "fit to the observations of this half of the file only (its \"halves\", "
                                      "e.g. fit in assets/reference-3d.json)");
    sub.add_option("--only", a->only, "fit to the observations with these ids only (repeat the flag or give a list "
                                      "a,b; with --half, ids of that half)")
        .delimiter(',');
    sub.add_option("--seeds", a->seeds, "seeds per scene, the same for every candidate: 1, 2, ..., N (default 2)")
        .check(Range(1, 1000));
    sub.add_option("--first-pass-seeds", a->first_pass_seeds,
                   "search with seeds 1..K (cheaper), then score the best candidate found with all --seeds and keep it "
                   "if it beats the start there (default 0: every evaluation at --seeds)");
    sub.add_option("--first-pass-grains", a->first_pass_grains,
                   fmt::format("search with grains this many times larger (the same fill mass: the window's coarser "
                               "models), then score the best candidate at the scene's grains and keep it if it beats "
                               "the start there (default 1: the scene's grains; 1 to {:g})",
                               kMaxFirstPassGrainScale));
    sub.add_option("--max-evals", a->max_evals,
                   fmt::format("optimiser evaluations after the start (default 24; 0 to {})", kMaxEvaluations));
    sub.add_option("--algorithm", a->algorithm, "NLopt method: sbplx (default), bobyqa, cobyla, neldermead");
    sub.add_option("--start", a->starts, "start FIELD=VALUE instead of the scene's own value (repeatable)");
    sub.add_option("--out", a->out, "folder: evaluations.csv, calibration.json, calibrated-scene.json, the runs "
                                    "(default runs/calibrate); the same command there resumes");
    // 0 is refused as sweep's and tradeoff's --jobs 0 are (leaving the flag out means all cores).
    sub.add_option("--jobs,-j", a->jobs, "runs at a time, 1 to 1024 (default: all cores)")
        .check(Range(1, 1024))
        .group("Running");
    sub.add_option("--shard", a->shard, "run slice K of N of every candidate's runs; the other slices' processes "
                                        "(the same command, other K, sharing --out) run the rest")
        .group("Running");
    sub.add_flag("--plan-only", a->plan_only, "print the plan and its estimated time, run nothing, write nothing")
        .group("Running");
    sub.add_flag("--force", a->force, "start over in a folder holding something else").group("Running");
    sub.add_flag("--quiet,-q", a->quiet, "no progress lines").group("Running");
    add_observation_scene_flags(sub, std::shared_ptr<ObservationSceneFlags>(a, &a->scene));
    return [a] { return run(*a); };
}

}  // namespace polyroll::cli
