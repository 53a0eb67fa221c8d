// Scene flags on the command line: see scene_options.h.
#include "cli/scene_options.h"

#include "sim/scene_json.h"

namespace polyroll::cli {

using json = nlohmann::ordered_json;

void SceneOptions::add_to(CLI::App& app) {
    scene_option_ = app.add_option("--scene", scene_file_, "scene file (JSON); flags given too override it")
                        ->group("Scene");
    auto flag = [&](CLI::Option* o, const std::string& field) {
        o->group("Scene");
        flags_.push_back({o, field});
    };
    flag(app.add_option("--model", model_, "physics: grains (Box2D shell and grains), segments or rigid "
                                           "(the experimenters' reduced models)"),
         "run.model");
    flag(app.add_option("--polygon", polygon_, "polygon preset (see 'polyroll presets'), e.g. hexagon-large"),
         "shell.preset");
    flag(app.add_option("--sides", sides_, "number of sides n, 3 to 64"), "shell.sides");
    flag(app.add_option("--fill", fill_, "fill ratio r, 0 to 1: share of the inside volume filled with grains"),
         "fill.ratio");
    flag(app.add_option("--material", material_, "fill material preset: bb, rice, peas"), "fill.material.preset");
    flag(app.add_option("--ramp", ramp_, "ramp preset: air-track, wooden"), "ramp.preset");
    flag(app.add_option("--angle", angle_, "ramp angle theta in degrees from horizontal, 0 to 89"),
         "ramp.angle_deg");
    flag(app.add_option("--release", release_, "release pose: vertex (held on a vertex) or face"), "release.pose");
    flag(app.add_option("--tilt", tilt_, "release tilt past balance, degrees"), "release.tilt_deg");
    flag(app.add_option("--fidelity", fidelity_, "fidelity preset: draft, standard, precise, reference"),
         "fidelity.preset");
    flag(app.add_option("--step-hz", step_hz_, "tracker steps per simulated second"), "fidelity.step_hz");
    flag(app.add_option("--substeps", substeps_, "engine steps per tracker step"), "fidelity.substeps");
    flag(app.add_option("--velocity-iterations", velocity_iterations_, "solver velocity iterations"),
         "fidelity.velocity_iterations");
    flag(app.add_option("--position-iterations", position_iterations_, "solver position iterations"),
         "fidelity.position_iterations");
    flag(app.add_option("--seed", seed_, "random seed for the grain packing"), "run.seed");
    flag(app.add_option("--time-limit", time_limit_, "longest simulated time, s"), "run.time_limit_s");
    flag(app.add_option("--sample-hz", sample_hz_, "trajectory rows per simulated second (default 30)"),
         "run.sample_hz");
}

Scene SceneOptions::resolve() const {
    std::vector<SceneLayer> layers;
    if (scene_option_ && scene_option_->count() > 0) layers.push_back(read_scene_file(scene_file_));
    SceneLayer cli;
    cli.origin = "command line";
    cli.doc = json::object();
    auto set = [&](const std::string& field, const json& value) {
        // "a.b.c" -> doc["a"]["b"]["c"]
        json* node = &cli.doc;
        size_t start = 0;
        for (size_t dot = field.find('.'); dot != std::string::npos; dot = field.find('.', start)) {
            node = &(*node)[field.substr(start, dot - start)];
            start = dot + 1;
        }
        (*node)[field.substr(start)] = value;
    };
    for (const Flag& f : flags_) {
        if (f.option->count() == 0) continue;
        cli.field_labels.emplace_back(f.field, f.option->get_name());
        if (f.field == "run.model") set(f.field, model_);
        else if (f.field == "shell.preset") set(f.field, polygon_);
        else if (f.field == "shell.sides") set(f.field, sides_);
        else if (f.field == "fill.ratio") set(f.field, fill_);
        else if (f.field == "fill.material.preset") set(f.field, material_);
        else if (f.field == "ramp.preset") set(f.field, ramp_);
        else if (f.field == "ramp.angle_deg") set(f.field, angle_);
        else if (f.field == "release.pose") set(f.field, release_);
        else if (f.field == "release.tilt_deg") set(f.field, tilt_);
        else if (f.field == "fidelity.preset") set(f.field, fidelity_);
        else if (f.field == "fidelity.step_hz") set(f.field, step_hz_);
        else if (f.field == "fidelity.substeps") set(f.field, substeps_);
        else if (f.field == "fidelity.velocity_iterations") set(f.field, velocity_iterations_);
        else if (f.field == "fidelity.position_iterations") set(f.field, position_iterations_);
        else if (f.field == "run.seed") set(f.field, seed_);
        else if (f.field == "run.time_limit_s") set(f.field, time_limit_);
        else if (f.field == "run.sample_hz") set(f.field, sample_hz_);
    }
    layers.push_back(cli);
    return resolve_scene(layers);
}

}  // namespace polyroll::cli
