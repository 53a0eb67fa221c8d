// Scene flags on the command line: see scene_options.h.
#include "cli/scene_options.h"

#include <cstdint>
#include <type_traits>

#include "sim/scene_json.h"

namespace polyroll::cli {

using json = nlohmann::ordered_json;

template <class T>
void SceneOptions::add_flag(CLI::App& app, const std::string& name, const std::string& field,
                            const std::string& help) {
    // The value lives on the heap so the flag's reader stays valid however flags_ grows.
    auto value = std::make_shared<T>();
    CLI::Option* o = app.add_option(name, *value, help)->group("Scene");
    // CLI11 converts "-1" to an unsigned type by wrapping it (--seed -1 became 2^64-1): refuse a sign.
    if constexpr (std::is_unsigned_v<T>)
        o->check(CLI::Validator(
            [](const std::string& text) {
                return text.find('-') == std::string::npos ? std::string()
                                                           : "must be a whole number from 0 to 2^64-1, got " + text;
            },
            "UINT"));
    flags_.push_back({o, field, [value] { return json(*value); }});
}

void SceneOptions::add_to(CLI::App& app) {
    scene_option_ = app.add_option("--scene", scene_file_, "scene file (JSON); flags given too override it")
                        ->group("Scene");
    add_flag<std::string>(app, "--model", "run.model",
                          "physics: grains (Box2D shell and grains), segments or rigid (the experimenters' "
                          "reduced models)");
    add_flag<std::string>(app, "--polygon", "shell.preset",
                          "polygon preset (see 'polyroll presets'), e.g. hexagon-large");
    add_flag<int>(app, "--sides", "shell.sides", "number of sides n, 3 to 64");
    add_flag<double>(app, "--fill", "fill.ratio", "fill ratio r, 0 to 1: share of the inside volume filled with grains");
    add_flag<std::string>(app, "--material", "fill.material.preset", "fill material preset: bb, rice, peas");
    add_flag<std::string>(app, "--ramp", "ramp.preset", "ramp preset: air-track, wooden");
    add_flag<double>(app, "--angle", "ramp.angle_deg", "ramp angle theta in degrees from horizontal, 0 to 89");
    add_flag<std::string>(app, "--release", "release.pose", "release pose: vertex (held on a vertex) or face");
    add_flag<double>(app, "--tilt", "release.tilt_deg", "release tilt past balance, degrees");
    add_flag<std::string>(app, "--fidelity", "fidelity.preset", "fidelity preset: draft, standard, precise, reference");
    add_flag<double>(app, "--step-hz", "fidelity.step_hz", "tracker steps per simulated second");
    add_flag<int>(app, "--substeps", "fidelity.substeps", "engine steps per tracker step");
    add_flag<int>(app, "--velocity-iterations", "fidelity.velocity_iterations", "solver velocity iterations");
    add_flag<int>(app, "--position-iterations", "fidelity.position_iterations", "solver position iterations");
    add_flag<std::uint64_t>(app, "--seed", "run.seed", "random seed for the grain packing");
    add_flag<double>(app, "--time-limit", "run.time_limit_s", "longest simulated time, s");
    add_flag<double>(app, "--sample-hz", "run.sample_hz", "trajectory rows per simulated second (default 30)");
}

Scene SceneOptions::resolve() const {
    std::vector<SceneLayer> layers;
    if (scene_option_ && scene_option_->count() > 0) layers.push_back(read_scene_file(scene_file_));
    SceneLayer cli;
    cli.origin = "command line";
    cli.doc = json::object();
    for (const Flag& f : flags_) {
        if (f.option->count() == 0) continue;
        cli.field_labels.emplace_back(f.field, f.option->get_name());
        // "a.b.c" -> doc["a"]["b"]["c"]
        json* node = &cli.doc;
        size_t start = 0;
        for (size_t dot = f.field.find('.'); dot != std::string::npos; dot = f.field.find('.', start)) {
            node = &(*node)[f.field.substr(start, dot - start)];
            start = dot + 1;
        }
        (*node)[f.field.substr(start)] = f.value();
    }
    layers.push_back(cli);
    return resolve_scene(layers);
}

}  // namespace polyroll::cli
