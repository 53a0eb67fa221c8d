// polyroll bench: real-time factor of a scene at each fidelity preset, tracked run against bare
// Box2D stepping of the same bodies, so the project's own overhead is visible. Single-threaded.
#include <algorithm>
#include <chrono>

#include <fmt/core.h>

#include "cli/bench_auto.h"
#include "cli/bench_calibration.h"
#include "cli/bench_dem3d.h"
#include "cli/bench_models.h"
#include "cli/bench_render.h"
#include "cli/bench_scaling.h"
#include "cli/commands.h"
#include "cli/scene_options.h"
#include "sim/assets.h"
#include "sim/grains/bare_engine.h"
#include "sim/scene/fidelity_preset.h"
#include "sim/model_registry.h"
#include "sim/scene/shell_label.h"
#include "sim/wall_clock.h"

namespace polyroll::cli {

namespace {

struct BenchOptions {
    SceneOptions scene;
    int repeats = 1;  // quick by default; --repeats 3 for figures to compare
    std::vector<std::string> presets;
    bool render_only = false, no_render = false;
    bool auto_only = false;
    // The slow rows opt in, each alone (--dem3d, --calibration, --scaling) or all with --all.
    bool dem3d_only = false, calibration_only = false, scaling_only = false, all = false;
    int ensemble = 0;  // with auto_only: members per shell of the ensemble table; 0: none
};


// Simulated seconds after the release for the grain-count rows: long enough for the first impacts,
// where the pile starts to tumble and its contacts churn.
constexpr double kScalingSimS = 1.5;
// And the same length again later in the roll, where the pile moves fast: the pile's frame
// (fidelity.frame) saves contacts in proportion to the pile's speed, so the first table shows it
// least. 3 s after the release is where issue 58 first measured the frame's gain.
constexpr double kScalingRollingFromS = 3.0;

void bench_scaling_tables(const std::string& fidelity, int repeats) {
    bench_scaling(fidelity, 0.0, kScalingSimS, repeats);
    bench_scaling(fidelity, kScalingRollingFromS, kScalingSimS, repeats);
}


int bench(const BenchOptions& o) {
    Scene base = o.scene.resolve();
    if (o.auto_only) {
        bench_auto(base, o.repeats);
        if (o.ensemble > 0) bench_auto_ensemble(base, o.ensemble);
        return kExitOk;
    }
    if (o.dem3d_only) {
        bench_dem3d(base, std::nullopt);
        return kExitOk;
    }
    if (o.scaling_only) {
        bench_scaling_tables(base.fidelity.preset, o.repeats);
        return kExitOk;
    }
    if (o.calibration_only) {
        bench_calibration("standard");
        return kExitOk;
    }
    if (o.render_only) {
        bench_rendering(base, o.repeats);
        return kExitOk;
    }
    std::vector<std::string> presets = o.presets;
    if (presets.empty()) presets = assets::preset_names(assets::Kind::fidelity);
    fmt::print("polyroll bench: {}, {} r = {:g}, {} at {:g} deg; best of {} on one core\n", shell_label(base),
               base.fill.material.preset + ",", base.fill.ratio,
               base.ramp.preset, base.ramp.angle_deg, o.repeats);
    fmt::print("{:<10} {:>9} {:>7} {:>8} {:>9} {:>9} {:>9} {:>9} {:>9}  {}\n", "fidelity", "step_s", "grains",
               "sim_s", "build_s", "run_s", "run_x_rt", "bare_x_rt", "overhead", "behaviour");
    std::optional<double> grain_run_s;  // at the scene's own fidelity, for the reduced models' speed-up
    for (const std::string& name : presets) {
        Scene s = at_fidelity_preset(base, name);
        s.run.model = reference_model();  // fidelity is the engine's: the grain simulation's
        double best_run = 1e300, best_bare = 1e300, best_build = 1e300;
        long steps = 0;
        RunResult last;
        for (int rep = 0; rep < o.repeats; ++rep) {
            auto t0 = WallClock::now();
            const std::unique_ptr<ModelRun> run = start_run(s);
            best_build = std::min(best_build, seconds_since(t0));
            t0 = WallClock::now();
            run->run_to_end();
            best_run = std::min(best_run, seconds_since(t0));
            steps = run->steps();
            last = run->result();

            // The same bodies, stepped the same number of times with nothing watching.
            best_bare = std::min(best_bare, time_bare_engine_s(s, steps));
        }
        const double sim_s = static_cast<double>(steps) / s.fidelity.step_hz;
        if (name == base.fidelity.preset) grain_run_s = best_build + best_run;
        fmt::print("{:<10} {:>9.6f} {:>7} {:>8.3f} {:>9.4f} {:>9.4f} {:>9.1f} {:>9.1f} {:>8.1f}%  {}\n", name,
                   1.0 / (s.fidelity.step_hz * s.fidelity.substeps), last.grains, sim_s, best_build, best_run,
                   sim_s / best_run, sim_s / best_bare, 100.0 * (best_run - best_bare) / best_bare,
                   to_string(last.measured.behaviour));
        std::fflush(stdout);
    }
    fmt::print("run_x_rt: simulated seconds per wall second with the tracker; bare_x_rt: Box2D stepping alone;\n"
               "overhead: tracker cost above bare stepping; build_s: building and settling the grains.\n");
    bench_models(base, o.repeats, grain_run_s);
    if (o.all) {
        bench_scaling_tables(base.fidelity.preset, o.repeats);
        bench_dem3d(base, grain_run_s);
        bench_calibration("standard");
    }
    if (!o.no_render) bench_rendering(base, o.repeats);
    return kExitOk;
}

}  // namespace

Action add_bench_command(Command& app) {
    auto opts = std::make_shared<BenchOptions>();
    Command sub = app.add_subcommand("bench", "measure speed: real-time factor per fidelity preset, and overhead "
                                              "over bare Box2D stepping");
    sub.footer(
        "Without flags: the scene at each fidelity preset, the reduced models and headless rendering, on one core. "
        "The slow rows opt in.\n"
        "Examples:\n"
        "  polyroll bench                                   # the default scene\n"
        "  polyroll bench --sides 8 --fill 0.375 --angle 13 --presets standard\n"
        "  polyroll bench --auto                            # auto against grains on the empty shells\n"
        "  polyroll bench --scaling --repeats 1             # cost per disc from 124 to 2,221 discs\n"
        "  polyroll bench --all                             # everything, the 3D reference and calibration too");
    opts->scene.add_to(sub);
    sub.add_option("--repeats", opts->repeats,
                   "runs per preset, the best reported (default 1: about 100 s for the default tables; 3 for "
                   "figures to compare)")
        .check(Range(1, 100));
    sub.add_option("--presets", opts->presets, "fidelity presets to measure (default: all)").delimiter(',');
    sub.add_flag("--render-only", opts->render_only, "measure only headless rendering (frames per second)");
    Flag auto_flag =
        sub.add_flag("--auto", opts->auto_only,
                     "measure only --model auto against grains on the empty n = 6, 8, 10, 18 at 5, 10, 20, 30 deg");
    sub.add_option("--ensemble", opts->ensemble,
                   "with --auto: also run each shell from this many releases 0.001 deg apart and compare the "
                   "models' mean terminal velocities and ranges (hopping shells are sensitive to tiny changes)")
        .check(Range(2, 50))
        .needs(auto_flag);
    Flag dem3d_flag = sub.add_flag(
        "--dem3d", opts->dem3d_only, "measure only the 3D reference (--model dem3d: one Yade run, about a minute)");
    Flag scaling_flag = sub.add_flag(
        "--scaling", opts->scaling_only,
        "measure only the grain engine's cost against the grains: six BB scenes from about 140 to 2,550 discs, "
        "each stepped in the ramp's frame, in the pile's, and in the pile's with contacts for near grains only: "
        "the cost per disc and step and Box2D's contacts per disc (two tables, from the release and from 3 s; "
        "several minutes a repeat)");
    Flag calibration_flag = sub.add_flag(
        "--calibration", opts->calibration_only,
        "measure only the calibration's cost: one evaluation of the bundled observations at standard, in the "
        "scene's grains and in grains 1.5x larger (about 4 minutes on one core), and the three-parameter fits they "
        "project");
    sub.add_flag("--all", opts->all,
                 "the default tables, then the grain-count rows, the 3D reference and the calibration's cost "
                 "(several minutes: the calibration row alone takes about 4 on one core)")
        .excludes(dem3d_flag)
        .excludes(scaling_flag)
        .excludes(calibration_flag)
        .excludes(auto_flag);
    sub.add_flag("--no-render", opts->no_render, "skip the headless rendering measurements");
    return [opts] { return bench(*opts); };
}

}  // namespace polyroll::cli
