// polyroll tradeoff: the measured speed/accuracy trade (src/sweep/tradeoff.h): runs the fixed study
// through the sweep engine (resumable), writes tradeoff.md, points.csv and tradeoff.png.
#include <filesystem>
#include <optional>
#include <thread>

#include <unistd.h>

#include <fmt/core.h>

#include "cli/commands.h"
#include "cli/interruptible_sweep.h"
#include "figures/figures_script.h"
#include "sim/message_text.h"
#include "sim/files/atomic_file.h"
#include "sim/dem3d/yade_process.h"
#include "sim/errors.h"
#include "sweep/sweep_runner.h"
#include "sweep/cross_section.h"
#include "sweep/tradeoff.h"

namespace polyroll::cli {

namespace {

namespace fs = std::filesystem;

struct TradeoffArgs {
    std::string out = "runs/tradeoff";
    std::string work;
    int jobs = 0;
    bool quiet = false;
    bool dem3d = false;
};

// Runs the study's plan in `work` (resuming what is there) and returns its results table; none if a
// Ctrl-C stopped it (the same command resumes).
std::optional<sweep::TableFile> run_study(const sweep::SweepPlan& plan, const fs::path& work, const TradeoffArgs& a) {
    std::error_code ec;
    if (fs::exists(sweep::plan_path(work), ec)) {
        if (sweep::plan_to_json(sweep::read_plan(work)) != sweep::plan_to_json(plan))
            throw InputError(fmt::format("--work {}: holds another plan (allowed: a new folder, or this study's)",
                                         work.string()));
    } else {
        prepare_output_dir(work, false);
        sweep::write_plan(work, plan);
    }
    sweep::SweepOptions o;
    o.dir = work;
    o.jobs = a.jobs > 0 ? a.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    o.quiet = a.quiet;
    fmt::print("polyroll tradeoff: {} into {}\n", counted(static_cast<long long>(plan.runs.size()), "run"), work.string());
    const sweep::SweepReport r = run_sweep_interruptibly(plan, o, "polyroll tradeoff");
    fmt::print("  {} run in {:.0f} s ({} failed), {} done before\n", r.ran, r.wall_time_s, r.failed, r.already);
    if (r.interrupted) return std::nullopt;
    return sweep::read_table(work / "results.csv");
}

// The --out folder made (or found) writable before anything else, so that a folder that cannot be
// written is named as given, not as its sweep/ subfolder the study's runs go into.
void check_out_folder(const fs::path& out) {
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec || !fs::is_directory(out) || ::access(out.c_str(), W_OK) != 0)
        throw InputError(fmt::format("--out {}: cannot be written ({}) (allowed: a folder you can write)", out.string(),
                                     ec ? ec.message() : std::string("not a writable folder")));
}

// The 2D cross-section against the 3D reference (sweep/cross_section.h).
int run_cross_section(const TradeoffArgs& a) {
    const fs::path out = a.out;
    const fs::path work = a.work.empty() ? out / "sweep-dem3d" : fs::path(a.work);
    dem3d::yade_command();  // a missing Yade is refused before the 2D half of the runs, not after
    check_out_folder(out);
    figures::figures_python();
    figures::figures_script();
    const sweep::SweepPlan plan = sweep::cross_section_plan();
    const std::optional<sweep::TableFile> table = run_study(plan, work, a);
    if (!table) return kExitInterrupted;
    const sweep::CrossSectionReport rep = sweep::analyse_cross_section(plan, *table, work);
    fs::create_directories(out);
    write_file_atomic(out / "cross-section.md", rep.markdown);
    write_file_atomic(out / "cross-section.csv", rep.maps_csv);
    const int code = figures::run_figures_script(
        {"cross-section", (out / "cross-section.csv").string(), (out / "cross-section.png").string()});
    if (code != 0) throw std::runtime_error(fmt::format("the figure script failed (exit code {})", code));
    fmt::print("  {}\n  {}\n  {}\n", (out / "cross-section.md").string(), (out / "cross-section.csv").string(),
               (out / "cross-section.png").string());
    return kExitOk;
}

int run(const TradeoffArgs& a) {
    if (a.dem3d) return run_cross_section(a);
    const fs::path out = a.out;
    const fs::path work = a.work.empty() ? out / "sweep" : fs::path(a.work);
    const sweep::SweepPlan plan = sweep::tradeoff_plan();
    figures::figures_python();  // missing matplotlib fails before an hour of runs, not after
    figures::figures_script();
    check_out_folder(out);
    const std::optional<sweep::TableFile> table = run_study(plan, work, a);
    if (!table) return kExitInterrupted;
    const sweep::TradeoffReport rep = sweep::analyse_tradeoff(plan, *table);
    fs::create_directories(out);
    write_file_atomic(out / "tradeoff.md", rep.markdown);
    write_file_atomic(out / "points.csv", rep.points_csv);
    const int code = figures::run_figures_script({"tradeoff", (out / "points.csv").string(), (out / "tradeoff.png").string()});
    if (code != 0) throw std::runtime_error(fmt::format("the figure script failed (exit code {})", code));
    fmt::print("  {}\n  {}\n", (out / "tradeoff.md").string(), (out / "points.csv").string());
    return kExitOk;
}

}  // namespace

Action add_tradeoff_command(Command& app) {
    auto a = std::make_shared<TradeoffArgs>();
    Command sub = app.add_subcommand("tradeoff", "measure error against cost for every model and fidelity preset");
    sub.footer(
        "Runs a fixed set of scenes with every model and preset (resumable: the same command continues),\n"
        "compares each with the converged reference and writes tradeoff.md, points.csv and tradeoff.png.\n"
        "With --dem3d, the 2D cross-section against the 3D reference instead: the 2D grain model without a\n"
        "closure, the same with the default pile-bulk closure, and the 3D reference (252 runs, a third of them in Yade: 23 minutes\n"
        "measured on 2 idle cores, 26 on busy ones, almost all of it the 3D runs; docs/guide.md): cross-section.md,\n"
        "cross-section.csv and cross-section.png.\n"
        "Examples:\n"
        "  polyroll tradeoff\n"
        "  polyroll tradeoff --dem3d --out docs/tradeoff");
    sub.add_option("--out", a->out, "folder for tradeoff.md, points.csv and tradeoff.png (default runs/tradeoff)");
    sub.add_flag("--dem3d", a->dem3d,
                 "the 2D grain model, with and without the default pile-bulk closure, against the 3D reference (Yade) "
                 "instead");
    sub.add_option("--work", a->work, "sweep folder for the runs (default OUT/sweep)");
    sub.add_option("--jobs,-j", a->jobs, "runs at a time (default: all cores)").check(Range(1, 1024));
    sub.add_flag("--quiet,-q", a->quiet, "no progress line");
    return [a] { return run(*a); };
}

}  // namespace polyroll::cli
