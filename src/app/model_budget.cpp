// The sandbox's physics budget: see model_budget.h.
#include "app/model_budget.h"

#include <cmath>

#include <fmt/format.h>

#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/fidelity_preset.h"
#include "sim/fill_plan.h"
#include "sim/scene_validate.h"

namespace polyroll::app {

namespace {

BudgetLevel level_from(const nlohmann::ordered_json& j) {
    BudgetLevel l;
    l.grain_scale = j.value("grain_scale", 1.0);
    l.fidelity = j.value("fidelity", std::string());
    l.terminal_velocity_error = j.at("terminal_velocity_error").get<double>();
    l.wrong_behaviours = j.at("wrong_behaviours").get<int>();
    l.scenes = j.at("scenes").get<int>();
    l.source = j.at("source").get<std::string>();
    return l;
}

BudgetFigures load_figures() {
    const auto& j = assets::file("sandbox-budget.json");
    BudgetFigures f;
    const auto& v = j.at("values");
    f.physics_s_per_grain_step = v.at("physics_s_per_grain_step").get<double>();
    f.physics_share = v.at("physics_share").get<double>();
    f.packing = v.at("packing").get<double>();
    f.cost_exponent = v.at("cost_exponent").get<double>();
    f.full_detail = level_from(j.at("full_detail"));
    for (const auto& l : j.at("levels")) f.levels.push_back(level_from(l));
    if (!(f.physics_s_per_grain_step > 0) || !(f.physics_share > 0) || !(f.packing > 0) ||
        !(f.cost_exponent >= 1.0 && f.cost_exponent <= 3.0) || f.levels.empty())
        throw InputError("assets/sandbox-budget.json: values.physics_s_per_grain_step, physics_share and packing must "
                         "be positive, cost_exponent 1 to 3 and levels not empty");
    return f;
}

// Engine steps per simulated second.
double engine_hz(const Scene& s) { return s.fidelity.step_hz * s.fidelity.substeps; }

// Whether the lane steps grains (auto does for a filled shell: model_choice.h).
bool steps_grains(const Scene& s) {
    return s.fill.ratio > 0.0 && (s.run.model == Model::grains || s.run.model == Model::automatic);
}

double grains_of(const Scene& s, double packing) { return steps_grains(s) ? packing * estimated_grain_count(s) : 0.0; }

// A level only coarsens: a scene already at a coarser step than the level's keeps its own.
Scene apply_level(const Scene& scene, const BudgetLevel& l) {
    if (!steps_grains(scene)) return scene;
    Scene s = with_coarser_grains(scene, l.grain_scale);
    if (!l.fidelity.empty()) {
        const Scene coarser = at_fidelity_preset(s, l.fidelity);
        if (engine_hz(coarser) < engine_hz(s)) s = coarser;
    }
    return s;
}

std::string percent(double share) { return fmt::format("{:.1f}%", 100.0 * share); }

std::string grains_text(double n) {
    // "about 1010": the estimate, rounded to tens; no thousands comma, where the panel's wrapping
    // would break the number.
    return fmt::format("{}", std::lround(n / 10.0) * 10);
}

}  // namespace

const BudgetFigures& budget_figures() {
    static const BudgetFigures f = load_figures();
    return f;
}

double grain_steps_per_engine_step(double grains, double cost_exponent) {
    return std::pow(grains + 1.0, cost_exponent);
}

double estimated_cost_s(const std::vector<Scene>& scenes, double cost_per_grain_step, const BudgetFigures& f) {
    double cost = 0.0;
    for (const Scene& s : scenes)
        cost += grain_steps_per_engine_step(grains_of(s, f.packing), f.cost_exponent) * engine_hz(s) * cost_per_grain_step;
    return cost;
}

BudgetChoice choose_model(const std::vector<Scene>& scenes, const BudgetFigures& f, double cost_per_grain_step,
                          bool measured, bool full_detail) {
    BudgetChoice c;
    c.full_detail_asked = full_detail;
    c.cost_per_grain_step = cost_per_grain_step;
    c.measured = measured;
    for (const Scene& s : scenes) c.grains_asked += grains_of(s, f.packing);
    c.cost_asked = estimated_cost_s(scenes, cost_per_grain_step, f);
    c.grains_chosen = c.grains_asked;
    c.cost_chosen = c.cost_asked;
    c.fits = c.cost_asked <= f.physics_share;
    if (full_detail || c.fits) return c;
    for (size_t i = 0; i < f.levels.size(); ++i) {
        BudgetChoice t = c;
        t.level = static_cast<int>(i);
        std::vector<Scene> reduced;
        try {
            reduced = apply_choice(scenes, f, t);
            for (const Scene& s : reduced) validate_scene(s);
        } catch (const InputError&) {
            continue;  // grains this large do not fit this shell: the next level cannot either
        }
        t.grains_chosen = 0.0;
        for (const Scene& s : reduced) t.grains_chosen += grains_of(s, f.packing);
        t.cost_chosen = estimated_cost_s(reduced, cost_per_grain_step, f);
        t.fits = t.cost_chosen <= f.physics_share;
        c = t;
        if (t.fits) break;
    }
    return c;
}

std::vector<Scene> apply_choice(const std::vector<Scene>& scenes, const BudgetFigures& f, const BudgetChoice& c) {
    if (!c.reduced()) return scenes;
    const BudgetLevel& l = f.levels.at(static_cast<size_t>(c.level));
    std::vector<Scene> out;
    out.reserve(scenes.size());
    for (const Scene& s : scenes) out.push_back(apply_level(s, l));
    return out;
}

std::string level_label(const BudgetLevel& level) {
    std::string label = level.grain_scale > 1.0 ? fmt::format("grains {:g}x larger", level.grain_scale) : "";
    if (!level.fidelity.empty()) label += (label.empty() ? "" : ", ") + level.fidelity + " step";
    return label;
}

std::string budget_statement(const BudgetChoice& c, const BudgetFigures& f) {
    if (c.full_detail_asked) {
        if (c.fits) return "Full detail: the scene as asked, within the physics budget for real time.";
        return fmt::format("Full detail: the scene as asked (about {} grains), slower than real time on this computer "
                           "(the line over the scene says how much).",
                           grains_text(c.grains_asked));
    }
    if (!c.reduced()) return "The scene as asked, within the physics budget for real time.";
    const BudgetLevel& l = f.levels.at(static_cast<size_t>(c.level));
    const std::string behaviours =
        l.wrong_behaviours == 0 ? fmt::format("the same behaviour in all {} scenes", l.scenes)
                                : fmt::format("behaviour changed in {} of {} scenes", l.wrong_behaviours, l.scenes);
    return fmt::format(
        "{}: {} (about {} -> {} grains, same fill mass). Costs, per the trade study: terminal velocity {} off on "
        "average (full detail {}), {}.{}",
        c.fits ? "To keep real time" : "Closer to real time (still slower)", level_label(l), grains_text(c.grains_asked),
        grains_text(c.grains_chosen), percent(l.terminal_velocity_error), percent(f.full_detail.terminal_velocity_error),
        behaviours, c.measured ? " Chosen from the cost measured on this computer." : "");
}

}  // namespace polyroll::app
