// The sandbox's physics budget: see model_budget.h.
#include "app/model_budget.h"

#include <cmath>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/scene/fidelity_preset.h"
#include "sim/grains/fill_plan.h"
#include "sim/model_registry.h"
#include "sim/scene/scene_validate.h"

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
    f.cost = run_cost_figures();
    f.physics_share = v.at("physics_share").get<double>();
    f.full_detail = level_from(j.at("full_detail"));
    for (const auto& l : j.at("levels")) f.levels.push_back(level_from(l));
    if (!(f.physics_share > 0) || f.levels.empty())
        throw InputError("assets/sandbox-budget.json: values.physics_share must be positive and levels not empty");
    return f;
}

// A level only coarsens: a scene already at a coarser step than the level's keeps its own.
Scene apply_level(const Scene& scene, const BudgetLevel& l) {
    if (!may_step_grains(scene)) return scene;
    Scene s = with_coarser_grains(scene, l.grain_scale);
    if (!l.fidelity.empty()) {
        const Scene coarser = at_fidelity_preset(s, l.fidelity);
        if (engine_steps_per_s(coarser.fidelity) < engine_steps_per_s(s.fidelity)) s = coarser;
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

namespace {

// One simulated second of a lane of `grains` grains, in seconds.
double lane_cost_s(const Scene& s, double grains, double s_per_cost_unit, const BudgetFigures& f) {
    return engine_step_units(grains, s.fidelity, f.cost) * engine_steps_per_s(s.fidelity) * s_per_cost_unit;
}

}  // namespace

double estimated_cost_s(const std::vector<Scene>& scenes, double s_per_cost_unit, const BudgetFigures& f) {
    double cost = 0.0;
    for (const Scene& s : scenes) cost += lane_cost_s(s, engine_grains(s, f.cost), s_per_cost_unit, f);
    return cost;
}

namespace {

// The estimate of the lanes with `level` applied (-1: as asked); throws InputError for grains too
// large for a shell.
BudgetChoice estimate(const std::vector<Scene>& scenes, const BudgetFigures& f, int level, double s_per_cost_unit,
                      bool measured) {
    BudgetChoice c;
    c.s_per_cost_unit = s_per_cost_unit;
    c.measured = measured;
    for (const Scene& s : scenes) c.grains_asked += engine_grains(s, f.cost);
    c.cost_asked = estimated_cost_s(scenes, s_per_cost_unit, f);
    c.level = level;
    const std::vector<Scene> stepped = apply_choice(scenes, f, c);
    if (c.reduced())
        for (const Scene& s : stepped) validate_scene(s);
    for (const Scene& s : stepped) c.grains_chosen += engine_grains(s, f.cost);
    c.cost_chosen = estimated_cost_s(stepped, s_per_cost_unit, f);
    c.fits = c.cost_chosen <= f.physics_share;
    double cost_after = 0.0;
    for (const Scene& s : stepped) {
        const double later = engine_grains_after_hand_over(s, f.cost);
        c.grains_on_hand_over += later;
        cost_after += lane_cost_s(s, later > 0 ? later : engine_grains(s, f.cost), s_per_cost_unit, f);
    }
    c.fits_after_hand_over = cost_after <= f.physics_share;
    return c;
}

}  // namespace

BudgetChoice offered_level(const std::vector<Scene>& scenes, const BudgetFigures& f, double s_per_cost_unit,
                           bool measured) {
    BudgetChoice c = estimate(scenes, f, -1, s_per_cost_unit, measured);
    if (c.fits) return c;
    for (size_t i = 0; i < f.levels.size(); ++i) {
        try {
            c = estimate(scenes, f, static_cast<int>(i), s_per_cost_unit, measured);
        } catch (const InputError&) {
            continue;  // grains this large do not fit this shell: the next level cannot either
        }
        if (c.fits) break;
    }
    return c;
}

BudgetChoice picked_level(const std::vector<Scene>& scenes, const BudgetFigures& f, int level,
                          double s_per_cost_unit, bool measured) {
    if (level < -1 || level >= static_cast<int>(f.levels.size()))
        throw InputError(fmt::format("model level {}: out of range (allowed: -1 to {})", level, f.levels.size() - 1));
    return estimate(scenes, f, level, s_per_cost_unit, measured);
}

std::string level_key(const BudgetLevel& level) {
    return fmt::format("{:g}x", level.grain_scale) + (level.fidelity.empty() ? "" : "-" + level.fidelity);
}

int level_from_key(const std::string& key, const BudgetFigures& f) {
    std::string allowed = "none";
    for (size_t i = 0; i < f.levels.size(); ++i) {
        if (level_key(f.levels[i]) == key) return static_cast<int>(i);
        allowed += ", " + level_key(f.levels[i]);
    }
    if (key == "none") return -1;
    throw InputError(fmt::format("--coarser {}: unknown (allowed: {})", key, allowed));
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

std::string level_errors(const BudgetLevel& level, const BudgetFigures& f) {
    const std::string behaviours =
        level.wrong_behaviours == 0
            ? fmt::format("the same behaviour in all {} scenes", level.scenes)
            : fmt::format("behaviour changed in {} of {} scenes", level.wrong_behaviours, level.scenes);
    return fmt::format("terminal velocity {} off on average (full detail {}), {}", percent(level.terminal_velocity_error),
                       percent(f.full_detail.terminal_velocity_error), behaviours);
}

std::string budget_statement(const BudgetChoice& stepped, const BudgetChoice& offer, const BudgetFigures& f) {
    if (stepped.reduced()) {
        const BudgetLevel& l = f.levels.at(static_cast<size_t>(stepped.level));
        return fmt::format("Stepping a cheaper model, as picked: {} (about {} -> {} grains, same fill mass){}. Costs, "
                           "per the trade study: {}.",
                           level_label(l), grains_text(stepped.grains_asked), grains_text(stepped.grains_chosen),
                           stepped.fits ? "" : ", still slower than real time here", level_errors(l, f));
    }
    // A full shell under auto steps no grains unless it is handed over: said, never counted as stepped.
    const std::string later =
        stepped.grains_on_hand_over > 0
            ? fmt::format(" A full shell runs as one rigid body and steps no grains; if it lifts off or slips, its "
                          "grains (about {}) take over{}.",
                          grains_text(stepped.grains_on_hand_over),
                          stepped.fits_after_hand_over ? "" : " and play slower than real time here")
            : std::string();
    if (stepped.fits) return "The scene as asked; it keeps real time on this computer." + later;
    std::string said = fmt::format("The scene as asked (about {} grains) costs more than real time on this computer: it "
                                   "plays slower (the line over the scene says how much), never differently.",
                                   grains_text(stepped.grains_asked));
    if (offer.reduced()) {
        const BudgetLevel& l = f.levels.at(static_cast<size_t>(offer.level));
        said += fmt::format(" Offered: {} (about {} -> {} grains, same fill mass), which {} real time here; per the "
                            "trade study: {}.",
                            level_label(l), grains_text(offer.grains_asked), grains_text(offer.grains_chosen),
                            offer.fits ? "keeps" : "comes closer to", level_errors(l, f));
    }
    if (stepped.measured) said += " Measured on this computer.";
    return said + later;
}

}  // namespace polyroll::app
