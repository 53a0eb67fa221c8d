// polyroll compare: one scene with each everyday model of the registry, side by side: what each
// level of modelling predicts and what it costs. With --out, each run's files and a combined
// speed-versus-time CSV.
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/scene_options.h"
#include "sim/files/atomic_file.h"
#include "sim/files/results_io.h"
#include "sim/model_registry.h"
#include "sim/scene/scene_json.h"
#include "sim/scene/shell_label.h"

namespace polyroll::cli {

namespace {

struct CompareOptions {
    SceneOptions scene;
    std::string out;
    bool force = false;
    bool json = false;
    bool dem3d = false;  // also the 3D reference, last (a minute of Yade a run)
};

std::string optional_number(const std::optional<double>& v, const char* format) {
    return v ? fmt::format(fmt::runtime(format), *v) : std::string("-");
}

// One row per sample time any run has; a run without a row at that time leaves its cell empty.
std::string speed_csv(const std::vector<RunResult>& runs) {
    std::map<long long, std::vector<std::optional<double>>> rows;  // keyed by time in nanoseconds
    for (size_t i = 0; i < runs.size(); ++i) {
        for (const TrajectorySample& s : runs[i].measured.trajectory) {
            auto& row = rows[std::llround(s.time_s * 1e9)];
            row.resize(runs.size());
            row[i] = s.speed_m_s;
        }
    }
    std::string csv = "time_s";
    for (const RunResult& r : runs) csv += fmt::format(",{}_speed_m_s", to_string(r.scene.run.model));
    csv += "\n";
    for (const auto& [ns, row] : rows) {
        csv += fmt::format("{:.6f}", static_cast<double>(ns) * 1e-9);
        for (const auto& v : row) csv += v ? fmt::format(",{:.6f}", *v) : std::string(",");
        csv += "\n";
    }
    return csv;
}

void print_table(const std::vector<RunResult>& runs) {
    const RunResult& ref = runs.front();
    const Scene& s = ref.scene;
    fmt::print("polyroll compare: {}, {} r = {:g}, {} at {:g} deg, {} fidelity for grains\n", shell_label(s),
               s.fill.material.preset.empty() ? "custom material," : s.fill.material.preset + ",", s.fill.ratio,
               s.ramp.preset.empty() ? "custom ramp" : s.ramp.preset, s.ramp.angle_deg,
               s.fidelity.preset.empty() ? "custom" : s.fidelity.preset);
    fmt::print("{:<9} {:<24} {:>10} {:>10} {:>8} {:>10} {:>11} {:>9}  {}\n", "model", "behaviour", "distance_m",
               "vt_m_s", "impacts", "mean_Q", "wall_s", "speed_up", "model valid");
    for (const RunResult& r : runs) {
        const Measurements& m = r.measured;
        const std::string valid = r.model_valid ? std::string("yes")
                                                : fmt::format("no: would hop from t = {:.3f} s",
                                                              r.model_invalid_time_s.value_or(0.0));
        fmt::print("{:<9} {:<24} {:>10.3f} {:>10} {:>8} {:>10} {:>11.6f} {:>9}  {}\n",
                   to_string(r.scene.run.model), to_string(m.behaviour), m.distance_m,
                   optional_number(m.terminal_velocity_m_s, "{:.3f}"), m.impacts.size(),
                   m.impacts.empty() ? std::string("-") : fmt::format("{:.4f}", mean_impact_ratio(m)), r.wall_time_s,
                   r.wall_time_s > 0.0 ? fmt::format("{:.0f}x", ref.wall_time_s / r.wall_time_s) : std::string("-"),
                   valid);
    }
    fmt::print("vt: terminal velocity (rolled to the end); mean_Q: mean kinetic-energy ratio over the face impacts;\n"
               "wall_s: one run on one core (grains: building and settling included); speed_up: over the grain model.\n");
}

// The table as JSON: the same rows and numbers, unrounded, null where the table prints '-'.
void print_json(const std::vector<RunResult>& runs, const std::string& out) {
    const RunResult& ref = runs.front();
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    auto optional = [](const std::optional<double>& v) { return v ? nlohmann::ordered_json(*v) : nullptr; };
    for (const RunResult& r : runs) {
        const Measurements& m = r.measured;
        rows.push_back({{"model", to_string(r.scene.run.model)},
                        {"behaviour", to_string(m.behaviour)},
                        {"distance_m", m.distance_m},
                        {"terminal_velocity_m_s", optional(m.terminal_velocity_m_s)},
                        {"impacts", m.impacts.size()},
                        {"mean_impact_energy_ratio",
                         m.impacts.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(mean_impact_ratio(m))},
                        {"wall_time_s", r.wall_time_s},
                        {"speed_up", r.wall_time_s > 0.0 ? nlohmann::ordered_json(ref.wall_time_s / r.wall_time_s)
                                                         : nlohmann::ordered_json(nullptr)},
                        {"model_valid", r.model_valid},
                        {"model_invalid_time_s", optional(r.model_invalid_time_s)}});
    }
    nlohmann::ordered_json doc = {{"scene", scene_to_json(ref.scene)}, {"runs", rows}};
    if (!out.empty()) doc["out"] = out;
    fmt::print("{}\n", doc.dump(2));
}

int compare(const CompareOptions& o) {
    const Scene base = o.scene.resolve();
    std::optional<std::filesystem::path> created;
    if (!o.out.empty()) created = prepare_output_dir(o.out, o.force);
    std::vector<RunResult> runs;
    try {
        std::vector<Model> models = everyday_models();  // the reference (grains) first: the others are timed against it
        if (o.dem3d) models.push_back(Model::dem3d);
        for (Model model : models) {
            Scene s = base;
            s.run.model = model;
            runs.push_back(run_scene(s));
        }
        if (!o.out.empty()) {
            const std::filesystem::path dir(o.out);
            for (const RunResult& r : runs) {
                const std::filesystem::path sub = dir / to_string(r.scene.run.model);
                std::filesystem::create_directories(sub);
                write_run_files(sub, r);
            }
            write_file_atomic(dir / "speed_vs_time.csv", speed_csv(runs));
        }
    } catch (...) {
        std::error_code ec;
        if (created) std::filesystem::remove_all(*created, ec);
        throw;
    }
    if (o.json) print_json(runs, o.out);
    else print_table(runs);
    if (!o.out.empty() && !o.json) {
        std::vector<Model> ran;
        ran.reserve(runs.size());
        for (const RunResult& r : runs) ran.push_back(r.scene.run.model);
        fmt::print("files: {0}/{{{1}}}/summary.json, trajectory.csv, impacts.csv; {0}/speed_vs_time.csv\n", o.out,
                   model_list(ran, ","));
    }
    for (const RunResult& r : runs) {
        if (r.measured.behaviour == Behaviour::diverged) {
            fmt::print(stderr, "polyroll: the {} run diverged {}\n", to_string(r.scene.run.model),
                       r.measured.divergence);
            return kExitDiverged;
        }
    }
    return kExitOk;
}

}  // namespace

Action add_compare_command(Command& app) {
    auto opts = std::make_shared<CompareOptions>();
    const std::string models = model_list(everyday_models());
    Command sub = app.add_subcommand(
        "compare", fmt::format("run one scene with every model ({}), side by side", models));
    sub.footer(fmt::format(
        "Examples:\n"
        "  polyroll compare\n"
        "  polyroll compare --sides 6 --fill 0.25 --angle 20 --out runs/cmp\n"
        "  polyroll compare --json > compare.json\n"
        "  polyroll compare --angle 14 --dem3d      # and the 3D reference\n"
        "Every model runs ({}); a --scene file's run.model is not used.\n"
        "Exit codes: 0 done, 2 bad input, 3 a run diverged, 1 other failure.",
        models));
    // No --model: compare runs every model, so the flag would be listed and ignored.
    opts->scene.add_to(sub, {"run.model"});
    sub.add_option("--out", opts->out,
                   fmt::format("folder for {}/ (each summary.json, trajectory.csv, impacts.csv) and speed_vs_time.csv",
                               model_list(everyday_models(), "/, ")))
        .group("Output");
    sub.add_flag("--force", opts->force, "write into an existing non-empty --out folder").group("Output");
    sub.add_flag("--json", opts->json, "print the table as JSON (the scene, then one object per model) instead")
        .group("Output");
    sub.add_flag("--dem3d", opts->dem3d,
                 "also run the 3D reference (Yade; about a minute for a whole-ramp run), into dem3d/");
    return [opts] { return compare(*opts); };
}

}  // namespace polyroll::cli
