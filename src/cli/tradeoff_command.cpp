// polyroll tradeoff: the measured speed/accuracy trade (src/sweep/tradeoff.h): runs the fixed study
// through the sweep engine (resumable), writes tradeoff.md, points.csv and tradeoff.png.
#include <filesystem>
#include <thread>

#include <fmt/format.h>

#include "cli/commands.h"
#include "figures/figures_script.h"
#include "sim/atomic_file.h"
#include "sim/errors.h"
#include "sweep/sweep_runner.h"
#include "sweep/tradeoff.h"

namespace polyroll::cli {

namespace {

namespace fs = std::filesystem;

struct TradeoffArgs {
    std::string out = "docs/tradeoff";
    std::string work;
    int jobs = 0;
    bool quiet = false;
};

int run(const TradeoffArgs& a) {
    const fs::path out = a.out;
    const fs::path work = a.work.empty() ? out / "sweep" : fs::path(a.work);
    const sweep::SweepPlan plan = sweep::tradeoff_plan();
    figures::figures_python();  // missing matplotlib fails before an hour of runs, not after
    figures::figures_script();
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
    fmt::print("polyroll tradeoff: {} runs into {}\n", plan.runs.size(), work.string());
    const sweep::SweepReport r = sweep::run_sweep(plan, o, nullptr);
    fmt::print("  {} run in {:.0f} s ({} failed), {} done before\n", r.ran, r.wall_time_s, r.failed, r.already);
    const sweep::TradeoffReport rep = sweep::analyse_tradeoff(plan, sweep::read_table(work / "results.csv"));
    fs::create_directories(out);
    write_file_atomic(out / "tradeoff.md", rep.markdown);
    write_file_atomic(out / "points.csv", rep.points_csv);
    const int code = figures::run_figures_script({"tradeoff", (out / "points.csv").string(), (out / "tradeoff.png").string()});
    if (code != 0) throw std::runtime_error(fmt::format("the figure script failed (exit code {})", code));
    fmt::print("  {}\n  {}\n", (out / "tradeoff.md").string(), (out / "points.csv").string());
    return kExitOk;
}

}  // namespace

Action add_tradeoff_command(CLI::App& app) {
    auto a = std::make_shared<TradeoffArgs>();
    CLI::App* sub = app.add_subcommand("tradeoff", "measure error against cost for every model and fidelity preset");
    sub->footer(
        "Runs a fixed set of scenes with every model and preset (resumable: the same command continues),\n"
        "compares each with the converged reference and writes tradeoff.md, points.csv and tradeoff.png.\n"
        "Example:\n"
        "  polyroll tradeoff --out docs/tradeoff");
    sub->add_option("--out", a->out, "folder for tradeoff.md, points.csv and tradeoff.png (default docs/tradeoff)");
    sub->add_option("--work", a->work, "sweep folder for the runs (default OUT/sweep)");
    sub->add_option("--jobs,-j", a->jobs, "runs at a time (default: all cores)")->check(CLI::Range(1, 1024));
    sub->add_flag("--quiet,-q", a->quiet, "no progress line");
    return [a] { return run(*a); };
}

}  // namespace polyroll::cli
