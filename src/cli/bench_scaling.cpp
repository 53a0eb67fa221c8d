// The grain engine's cost against the grains in polyroll bench: see bench_scaling.h.
#include "cli/bench_scaling.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <optional>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "sim/assets.h"
#include "sim/grains/bare_engine.h"
#include "sim/scene/scene_json.h"
#include "sim/scene/scene_names.h"
#include "sim/scene/shell_label.h"
#include "sim/run_cost.h"

namespace polyroll::cli {

namespace {

struct ScalingScene {
    const char* shell;
    double fill_ratio;
};

// BBs on the air track at 20 degrees, the default scene's ramp: the small shells' fills span the
// experiment's small polygons, the large hexagon's its largest piles (the `hexagon-large-bb`
// preset is the half-full one).
constexpr ScalingScene kScenes[] = {
    {"hexagon-small", 0.25}, {"hexagon-small", 0.5},  {"decagon-small", 0.75},
    {"hexagon-large", 0.25}, {"hexagon-large", 0.5}, {"hexagon-large", 0.75},
};

// How the engine steps: its frame and which grain pairs it keeps contacts for. Each scene is stepped
// as Box2D alone would (the ramp's frame, its own contacts), in the pile's frame, and in the pile's
// frame with near contacts only.
struct Engine {
    EngineFrame frame;
    GrainContacts contacts;
};
constexpr Engine kEngines[] = {
    {EngineFrame::ramp, GrainContacts::boxes},
    {EngineFrame::pile, GrainContacts::boxes},
    {EngineFrame::pile, GrainContacts::near},
};

Scene scaling_scene(const ScalingScene& row, const std::string& fidelity, Engine engine) {
    nlohmann::ordered_json doc = {
        {"shell", {{"preset", row.shell}}},
        {"fill", {{"ratio", row.fill_ratio}, {"material", "bb"}}},
        {"ramp", {{"preset", "air-track"}, {"angle_deg", 20.0}}},
        {"fidelity", {{"preset", fidelity}, {"frame", to_string(engine.frame)}, {"contacts", to_string(engine.contacts)}}},
    };
    return resolve_scene({SceneLayer{doc, "polyroll bench --scaling", {}}});
}

struct Row {
    Scene scene;
    EngineLoad load;
    double s_per_step = 0.0;  // engine steps (substeps included)
};

// Least squares of ln(cost per step) on ln(grains + 1): the budget's power law.
struct PowerLaw {
    double exponent = 0.0, s_per_grain_step = 0.0;
};
PowerLaw fit_power_law(const std::vector<Row>& rows) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = static_cast<double>(rows.size());
    for (const Row& r : rows) {
        const double x = std::log(r.load.grains + 1.0), y = std::log(r.s_per_step);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    PowerLaw p;
    p.exponent = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    p.s_per_grain_step = std::exp((sy - p.exponent * sx) / n);
    return p;
}

}  // namespace

void bench_scaling(const std::string& fidelity, double from_s, double sim_s, int repeats) {
    const std::string stretch = from_s > 0.0 ? fmt::format("{:g} s from {:g} s after the release (stepped there untimed)",
                                                          sim_s, from_s)
                                             : fmt::format("the first {:g} s after the release", sim_s);
    fmt::print("\ngrain engine against grains: BBs on the air track at 20 deg, {} fidelity, {} stepped bare, best of "
               "{}; one core; each scene stepped in the ramp's frame and in the pile's (fidelity.frame), and in the "
               "pile's with contacts only for near grains (fidelity.contacts)\n",
               fidelity, stretch, repeats);
    fmt::print("{:<34} {:>7} {:>6} {:>8} {:>10} {:>12} {:>10} {:>12} {:>14} {:>10} {:>9} {:>8} {:>9}\n", "scene",
               "grains", "frame", "contacts", "ms_step", "us_grain_step", "x_first", "x_real_time", "contacts/grain", "touching", "speed_m_s",
               "timed_s", "x_faster");
    const Scene defaults = resolve_scene({});
    std::vector<Row> rows;  // stepped as the defaults step, for the power law
    std::optional<double> first_us[std::size(kEngines)];  // us a disc and step of each engine's first row
    for (const ScalingScene& spec : kScenes) {
        std::optional<double> ramp_s_per_step;
        for (std::size_t e = 0; e < std::size(kEngines); ++e) {
            const Engine engine = kEngines[e];
            const std::string frame = to_string(engine.frame), contacts = to_string(engine.contacts);
            Row row;
            row.scene = scaling_scene(spec, fidelity, engine);
            const std::string label = fmt::format("{}, r = {:g}", shell_label(row.scene), spec.fill_ratio);
            const long steps = std::lround(sim_s * row.scene.fidelity.step_hz);
            const long skip = std::lround(from_s * row.scene.fidelity.step_hz);
            // Per engine step, as the budget counts them; the best of the repeats.
            const auto per_step = [&](const EngineLoad& l) {
                return l.wall_s / static_cast<double>(l.timed_steps * row.scene.fidelity.substeps);
            };
            for (int rep = 0; rep < repeats; ++rep) {
                const EngineLoad load = measure_engine_load(row.scene, steps, skip);
                if (load.timed_steps == 0) {
                    row.load = load;
                    break;
                }
                if (rep == 0 || per_step(load) < row.s_per_step) row.load = load, row.s_per_step = per_step(load);
            }
            if (row.load.timed_steps == 0) {  // the shell passed the run's end before the stretch began
                fmt::print("{:<34} {:>7} {:>6} {:>8} the shell was past the ramp's end by {:g} s\n", label,
                           row.load.grains, frame, contacts, from_s);
                continue;
            }
            const double us_per_grain_step = 1e6 * row.s_per_step / std::max(1, row.load.grains);
            std::optional<double>& first = first_us[e];
            if (!first) first = us_per_grain_step;
            if (e == 0) ramp_s_per_step = row.s_per_step;
            const std::string faster = e > 0 && ramp_s_per_step ? fmt::format("{:.2f}", *ramp_s_per_step / row.s_per_step)
                                                                : "";
            const double timed_s = static_cast<double>(row.load.timed_steps) / row.scene.fidelity.step_hz;
            fmt::print("{:<34} {:>7} {:>6} {:>8} {:>10.3f} {:>12.2f} {:>10.2f} {:>12.3f} {:>14.1f} {:>10.1f} {:>9.3f} "
                       "{:>8.2f} {:>9}\n",
                       label, row.load.grains, frame, contacts, 1e3 * row.s_per_step, us_per_grain_step,
                       us_per_grain_step / *first, timed_s / row.load.wall_s, row.load.contacts_per_grain,
                       row.load.touching_per_grain, row.load.shell_speed_m_s, timed_s, faster);
            std::fflush(stdout);
            if (engine.frame == defaults.fidelity.frame && engine.contacts == defaults.fidelity.contacts) rows.push_back(row);
        }
    }
    const RunCostFigures& model = run_cost_figures();
    if (rows.size() >= 2) {  // a fit needs two grain counts
        const PowerLaw fit = fit_power_law(rows);
        fmt::print("fitted, stepped as the defaults step ({}, {}): cost per step = {:.3g} s x (grains + 1)^{:.2f}; the cost model every estimate uses "
               "(assets/run-cost.json: engine_step_s, engine_exponent, at {:g} iterations) says {:.3g} s x "
               "(grains + 1)^{:.2f}\n",
               to_string(defaults.fidelity.frame), to_string(defaults.fidelity.contacts), fit.s_per_grain_step, fit.exponent, model.engine_reference_iterations, model.engine_step_s,
               model.engine_exponent);
    }
    fmt::print("us_grain_step: engine time per disc and step; x_first: that against the first row; contacts/grain: "
               "Box2D's contacts per disc, sampled every 100 steps: with its own (boxes), pairs of fixtures whose boxes, "
               "enlarged by 0.1 engine units and four steps' travel, overlap; with near, the grain pairs within its "
               "linear slop (0.005 units) of touching; touching: of those, the ones whose shapes touch; speed_m_s: the "
               "shell's speed down the ramp where the timing began (each frame's run is its own, so a shell that has "
               "stopped in one frame and not the other shows here); timed_s: the simulated seconds timed, fewer where the "
               "shell reached the ramp's end; x_faster: the time a step of the first "
               "line (the ramp's frame, Box2D's own contacts) over this line's.\n");
}

}  // namespace polyroll::cli
