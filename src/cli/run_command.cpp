// polyroll run: one scene, a human summary (or JSON) on stdout, the files with --out.
#include <filesystem>
#include <cstdio>
#include <optional>
#include <string>

#include <unistd.h>

#include <fmt/core.h>

#include "cli/commands.h"
#include "cli/interrupt_cleanup.h"
#include "cli/run_progress_line.h"
#include "cli/scene_options.h"
#include "sim/files/atomic_file.h"
#include "sim/message_text.h"
#include "sim/model_registry.h"
#include "sim/files/results_io.h"
#include "sim/run_progress.h"
#include "sim/scene/scene_json.h"
#include "sim/scene/shell_label.h"

namespace polyroll::cli {

namespace {

struct RunOptions {
    SceneOptions scene;
    std::string out;
    bool json = false;
    bool force = false;
};

// The summary's values start in this column; the auto model's reason (once 600 characters on one
// line) is wrapped to lines of at most kLineWidth under it.
constexpr std::size_t kWhyIndent = 21, kLineWidth = 100;

std::string wrapped(const std::string& text, std::size_t indent) {
    std::string out, line;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find(' ', start);
        if (end == std::string::npos) end = text.size();
        const std::string word = text.substr(start, end - start);
        start = end + 1;
        if (word.empty()) continue;
        if (!line.empty() && indent + line.size() + 1 + word.size() > kLineWidth) {
            out += line + "\n" + std::string(indent, ' ');
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    return out + line;
}

std::string describe_scene(const RunResult& r) {
    const Scene& s = r.scene;
    // Fidelity means the engine's step and iterations: only the grain model has them.
    const Model ran = model_that_ran(r);
    std::string physics = model_traits(ran).engine
                              ? (s.fidelity.preset.empty() ? "custom" : s.fidelity.preset) + " fidelity"
                              : to_string(ran) + " model";
    if (r.model_choice) physics = "auto model, " + physics;
    const std::string release = s.release.pose == ReleasePose::tipped ? "filled on a face, released on a vertex"
                                                                      : "released on a " + to_string(s.release.pose);
    return fmt::format("{}, {} r = {:g}, {} at {:g} deg, {}, {}", shell_label(s),
                       s.fill.material.preset.empty() ? "custom material," : s.fill.material.preset + ",",
                       s.fill.ratio, s.ramp.preset.empty() ? "custom ramp" : s.ramp.preset, s.ramp.angle_deg,
                       release, physics);
}

void print_summary(const RunResult& r, const std::string& out) {
    const Measurements& m = r.measured;
    fmt::print("polyroll run: {}\n", describe_scene(r));
    if (r.model_choice) {
        const ModelChoice& c = *r.model_choice;
        const std::string flight =
            c.lift_off_time_s
                ? fmt::format(", free to leave the ramp from t = {:.3f} s (where it would lift off or slip)",
                              *c.lift_off_time_s)
                : std::string(" (it never lifts off)");
        if (c.hand_over_time_s)
            fmt::print("  model              {}{}, handed over to {} at t = {:.3f} s ({})\n", to_string(c.model), flight,
                       to_string(*c.then), *c.hand_over_time_s, c.hand_over_why);
        else if (c.then)
            fmt::print("  model              {}{}; no hand-over to {}\n", to_string(c.model), flight,
                       to_string(*c.then));
        else
            fmt::print("  model              {}\n", to_string(c.model));
        fmt::print("  why                {}\n", wrapped(c.reason, kWhyIndent));
    }
    fmt::print("  behaviour          {}\n", to_string(m.behaviour));
    if (m.behaviour == Behaviour::diverged) fmt::print("  divergence         {}\n", m.divergence);
    if (!r.model_valid)
        fmt::print("  model valid        no: from t = {:.3f} s the {} model needs a negative normal force (the real "
                   "polygon would hop); its numbers after that mean little\n",
                   r.model_invalid_time_s.value_or(0.0), to_string(model_that_ran(r)));
    fmt::print("  distance           {:.3f} m\n", m.distance_m);
    if (m.terminal_velocity_m_s && m.terminal_velocity_faces > 0)
        fmt::print("  terminal velocity  {:.3f} m/s (mean over the last {} faces)\n", *m.terminal_velocity_m_s,
                   m.terminal_velocity_faces);
    else if (m.terminal_velocity_m_s)  // no face rhythm to time (a sliding or hopping shell): the trajectory's
        fmt::print("  terminal velocity  {:.3f} m/s (mean speed over the last tenth of the run: fewer than two "
                   "face impacts)\n",
                   *m.terminal_velocity_m_s);
    else
        fmt::print("  terminal velocity  - (only when it rolls to the end)\n");
    if (m.impacts.empty())
        fmt::print("  face impacts       0\n");
    else
        fmt::print("  face impacts       {} (mean kinetic energy ratio {:.3f})\n", m.impacts.size(),
                   mean_impact_ratio(m));
    fmt::print("  time               {:.3f} s simulated in {:.3g} s ({})\n", m.end_time_s,
               r.wall_time_s, real_time_text(m.end_time_s, r.wall_time_s));
    if (r.grains > 0)
        fmt::print("  grains             {} ({} inside at the end), fill mass {:.4f} kg\n", r.grains, m.grains_inside,
                   r.fill_mass_kg);
    else if (r.fill_mass_kg > 0.0)
        fmt::print("  fill               {:.4f} kg as {} (no grains in the {} model)\n", r.fill_mass_kg,
                   model_traits(model_that_ran(r)).fill_description, to_string(model_that_ran(r)));
    else
        fmt::print("  grains             none (empty shell)\n");
    // The 3D reference in a channel (its summary block, RunResult::model_blocks).
    const auto yade = r.model_blocks.json().find("dem3d_engine");
    if (yade != r.model_blocks.json().end() && yade->contains("channel")) {
        const auto& c = yade->at("channel");
        fmt::print("  in the channel     moved {:.1f} mm across, yawed {:.2f} deg, tilted {:.2f} deg; touched its sides in "
                   "{} of {} steps (at most {:.3g} N)\n",
                   1000.0 * c.at("max_offset_m").get<double>(), c.at("max_yaw_deg").get<double>(),
                   c.at("max_tilt_deg").get<double>(), c.at("steps_touching").get<long>(), c.at("steps").get<long>(),
                   c.at("max_side_force_N").get<double>());
    }
    // Joined as paths: --out runs/a/ must not print runs/a//summary.json.
    if (!out.empty())
        fmt::print("  files              {}, trajectory.csv, impacts.csv\n",
                   (std::filesystem::path(out) / "summary.json").string());
}

int run(const RunOptions& o) {
    const Scene scene = o.scene.resolve();
    std::optional<std::filesystem::path> created;
    if (!o.out.empty()) created = prepare_output_dir(o.out, o.force);
    const CleanUpOnInterrupt on_interrupt("polyroll run", created);
    RunResult r;
    try {
        // A model whose runs take minutes (the 3D reference) says how far it has got and the time left.
        std::optional<RunProgressLine> line;
        std::optional<ScopedRunProgress> progress;
        if (may_report_progress(scene)) {
            line.emplace(scene, ::isatty(2) != 0);
            progress.emplace([&line](double t, double x) { line->report(t, x); });
        }
        r = run_scene(scene);
        if (progress) {
            progress.reset();
            line->finish();
        }
        if (!o.out.empty()) write_run_files(o.out, r);
    } catch (...) {
        // Nothing half-written: a folder this run created goes with it.
        std::error_code ec;
        if (created) std::filesystem::remove_all(*created, ec);
        throw;
    }
    if (o.json)
        fmt::print("{}\n", summary_json(r).dump(2));
    else
        print_summary(r, o.out);
    if (r.measured.behaviour == Behaviour::diverged) {
        fmt::print(stderr, "polyroll: the run diverged {}\n", r.measured.divergence);
        return kExitDiverged;
    }
    return kExitOk;
}

}  // namespace

Action add_run_command(Command& app) {
    auto opts = std::make_shared<RunOptions>();
    Command sub = app.add_subcommand("run", "run one scene and report what the experiment measured");
    sub.footer(
        "Examples:\n"
        "  polyroll run\n"
        "  polyroll run --sides 8 --fill 0.375 --material rice --angle 14 --out runs/oct-rice\n"
        "  polyroll run --scene my-scene.json --json\n"
        "  polyroll run --set fill.material.wall_friction=0.05 --set ramp.length_m=1.5\n"
        "  polyroll run --preset hexagon-large-rice           # a preset of the window (polyroll presets)\n"
        "  polyroll run --preset race --lane 2                # one lane of a race\n"
        "Exit codes: 0 done, 2 bad input, 3 the run diverged (its files say where), 130 interrupted (the folder it\n"
        "made is removed), 1 other failure.");
    opts->scene.add_to(sub);
    opts->scene.add_preset_to(sub);
    sub.add_option("--out", opts->out, "folder for summary.json, trajectory.csv and impacts.csv").group("Output");
    sub.add_flag("--json", opts->json, "print the summary as JSON instead of text").group("Output");
    sub.add_flag("--force", opts->force, "write into an existing non-empty --out folder").group("Output");
    return [opts] { return run(*opts); };
}

}  // namespace polyroll::cli
