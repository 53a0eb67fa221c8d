// The model registry: see model_registry.h.
#include "sim/model_registry.h"

#include <algorithm>
#include <chrono>

#include <fmt/core.h>

#include "sim/errors.h"
#include "sim/model_choice.h"
#include "sim/scene/scene_names.h"

namespace polyroll {

namespace {

const ModelRow& row(Model model) {
    for (const ModelRow& r : model_rows())
        if (r.traits.model == model) return r;
    throw InputError(fmt::format("model {}: not in the model registry", static_cast<int>(model)));
}

}  // namespace

const std::vector<Model>& all_models() {
    static const std::vector<Model> models = [] {
        std::vector<Model> m;
        for (const ModelRow& r : model_rows()) m.push_back(r.traits.model);
        return m;
    }();
    return models;
}

const std::vector<Model>& everyday_models() {
    static const std::vector<Model> models = [] {
        std::vector<Model> m;
        for (const ModelRow& r : model_rows())
            if (r.traits.everyday) m.push_back(r.traits.model);
        return m;
    }();
    return models;
}

const std::vector<std::string>& window_model_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (Model m : everyday_models()) n.push_back(to_string(m));
        n.push_back(to_string(Model::automatic));
        return n;
    }();
    return names;
}

Model reference_model() { return all_models().front(); }

std::string model_list(const std::vector<Model>& models, const char* separator) {
    std::string list;
    for (Model m : models) list += (list.empty() ? "" : separator) + to_string(m);
    return list;
}

std::string model_help(const std::vector<Model>& models) {
    std::string help;
    for (Model m : models) {
        const ModelTraits& t = model_traits(m);
        // A model that assumes one slope says so here, where a user picks a model.
        help += fmt::format("{} ({}{}), ", to_string(m), t.description,
                            t.follows_curved_track ? "" : "; straight ramps only");
    }
    return help + fmt::format("or {} ({})", to_string(Model::automatic), auto_rule_description());
}

std::vector<Model> models_a_run_may_use(const Scene& scene) {
    if (scene.run.model != Model::automatic) return {scene.run.model};
    const ModelChoice c = choose_model(scene);
    if (c.then) return {c.model, *c.then};
    return {c.model};
}

bool may_report_progress(const Scene& scene) {
    const std::vector<Model> models = models_a_run_may_use(scene);
    return std::any_of(models.begin(), models.end(), [](Model m) { return model_traits(m).reports_progress; });
}

bool may_step_grains(const Scene& scene) {
    if (scene.fill.ratio <= 0.0) return false;
    const std::vector<Model> models = models_a_run_may_use(scene);
    // The 3D reference has grains too, but Yade steps them in its own process, not polyroll.
    return std::any_of(models.begin(), models.end(), [](Model m) {
        const ModelTraits& t = model_traits(m);
        return t.engine && t.has_grains;
    });
}

bool steps_grains_from_start(const Scene& scene) {
    if (scene.fill.ratio <= 0.0) return false;
    const ModelTraits& t = model_traits(models_a_run_may_use(scene).front());
    return t.engine && t.has_grains;
}

const ModelTraits& model_traits(Model model) { return row(model).traits; }

std::unique_ptr<ModelRun> start_run(const Scene& scene) {
    // auto is a rule over the rows, not a row: it never appears in all_models() (compare, bench).
    if (scene.run.model == Model::automatic) return start_auto_run(scene);
    return row(scene.run.model).start(scene);
}

std::unique_ptr<ModelRun> continue_run(const Scene& scene, const HandOver& from) {
    const ModelRow& r = row(scene.run.model);
    if (!r.carry_on)
        throw InputError(fmt::format("the {} model cannot carry on a run another model began", to_string(scene.run.model)));
    return r.carry_on(scene, from);
}

std::unique_ptr<ModelRun> start_run_while_valid(const Scene& scene) {
    const ModelRow& r = row(scene.run.model);
    if (!r.start_while_valid)
        throw InputError(fmt::format("the {} model has no run that ends where it stops holding", to_string(scene.run.model)));
    return r.start_while_valid(scene);
}

RunResult run_scene(const Scene& scene) {
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<ModelRun> run = start_run(scene);
    run->run_to_end();
    RunResult r = run->result();
    r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace polyroll
