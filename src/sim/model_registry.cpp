// The model registry: see model_registry.h.
#include "sim/model_registry.h"

#include <chrono>

#include <fmt/format.h>

#include "sim/auto_run.h"
#ifndef __EMSCRIPTEN__
#include "sim/dem3d/dem3d_run.h"
#endif
#include "sim/errors.h"
#include "sim/models/reduced_run.h"
#include "sim/scene_json.h"
#include "sim/simulation.h"

namespace polyroll {

namespace {

struct ModelRow {
    ModelTraits traits;
    std::unique_ptr<ModelRun> (*start)(const Scene& scene);
    std::unique_ptr<ModelRun> (*carry_on)(const Scene& scene, const HandOver& from);  // null: cannot
};

std::unique_ptr<ModelRun> start_grains(const Scene& s) { return std::make_unique<Simulation>(s); }
std::unique_ptr<ModelRun> carry_on_grains(const Scene& s, const HandOver& from) {
    return std::make_unique<Simulation>(s, from);
}
std::unique_ptr<ModelRun> start_segments(const Scene& s) {
    return std::make_unique<models::ReducedRun>(s, models::FillMotion::relevel);
}
std::unique_ptr<ModelRun> start_rigid(const Scene& s) {
    return std::make_unique<models::ReducedRun>(s, models::FillMotion::frozen);
}
std::unique_ptr<ModelRun> start_dem3d([[maybe_unused]] const Scene& s) {
#ifdef __EMSCRIPTEN__
    throw InputError("--model dem3d runs Yade as a separate program, which a web page cannot: use polyroll run "
                     "--model dem3d");
#else
    return std::make_unique<dem3d::Dem3dRun>(s);
#endif
}

const std::vector<ModelRow>& rows() {
    static const std::vector<ModelRow> table = {
        {{Model::grains, true, true, "", true, true, true}, start_grains, carry_on_grains},
        {{Model::segments, false, false, "segments re-levelled at each impact", false, true, false}, start_segments,
         nullptr},
        {{Model::rigid, false, false, "a frozen rigid body", false, true, false}, start_rigid, nullptr},
        {{Model::dem3d, false, true, "", false, false, true}, start_dem3d, nullptr},
    };
    return table;
}

const ModelRow& row(Model model) {
    for (const ModelRow& r : rows())
        if (r.traits.model == model) return r;
    throw InputError(fmt::format("model {}: not in the model registry", static_cast<int>(model)));
}

}  // namespace

const std::vector<Model>& all_models() {
    static const std::vector<Model> models = [] {
        std::vector<Model> m;
        for (const ModelRow& r : rows()) m.push_back(r.traits.model);
        return m;
    }();
    return models;
}

const std::vector<Model>& everyday_models() {
    static const std::vector<Model> models = [] {
        std::vector<Model> m;
        for (const ModelRow& r : rows())
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

const ModelTraits& model_traits(Model model) { return row(model).traits; }

std::unique_ptr<ModelRun> start_run(const Scene& scene) {
    // auto is a rule over the rows, not a row: it never appears in all_models() (compare, bench).
    if (scene.run.model == Model::automatic) return std::make_unique<AutoRun>(scene);
    return row(scene.run.model).start(scene);
}

std::unique_ptr<ModelRun> continue_run(const Scene& scene, const HandOver& from) {
    const ModelRow& r = row(scene.run.model);
    if (!r.carry_on)
        throw InputError(fmt::format("the {} model cannot carry on a run another model began", to_string(scene.run.model)));
    return r.carry_on(scene, from);
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
