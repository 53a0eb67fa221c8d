// Scene flags on the command line: see scene_options.h.
#include "cli/scene_options.h"

#include <algorithm>
#include <cstdint>
#include <exception>
#include <type_traits>

#include <fmt/core.h>

#include "sim/errors.h"
#include "sim/scene/field_text.h"
#include "sim/scene/json_path.h"
#include "sim/scene/scene_fields.h"
#include "sim/scene/scene_json.h"
#include "sweep/grid_values.h"
#include "sweep/sweep_plan.h"

namespace polyroll::cli {

using json = nlohmann::ordered_json;

std::string default_note(const SceneField& f) {
    static const json defaults = [] {
        try {
            return scene_to_json(resolve_scene({}));
        } catch (const std::exception&) {
            return json::object();
        }
    }();
    // A preset field is the section's "preset" key.
    const json* node = find_at(defaults, f.path);
    if (node == nullptr || node->is_null() || node->is_object()) return "";
    return " (default: " + sweep::value_text(*node) + ")";
}

template <class T>
void SceneOptions::add_flag(flags::Command& app, const SceneField& f, const std::string& help) {
    // The value lives on the heap so the flag's reader stays valid however flags_ grows.
    auto value = std::make_shared<T>();
    const std::string name(f.flag), field(f.path);
    flags::Flag o = app.add_option(name, *value, help).group("Scene");
    // The typed text read as every surface reads it (sim/scene/field_text.h), before CLI11 converts it:
    // CLI11 would wrap "-1" into a seed of 2^64-1 and clamp digits past 2^64-1 to it. The refusal is
    // "TEXT: PROBLEM"; flags::flag_error_text says it as "--seed -1: not a whole number (allowed: ...)".
    if constexpr (!std::is_same_v<T, std::string>)
        o.check([&f](const std::string& text) {
            const std::string problem = field_text_problem(f, text);
            return problem.empty() ? std::string() : text + ": " + problem;
        });
    flags_.push_back({o, field, [value] { return json(*value); }});
}

void SceneOptions::add_to(flags::Command& app, const std::vector<std::string>& without) {
    without_ = without;
    scene_option_ = app.add_option("--scene", scene_file_, "scene file (JSON); flags given too override it")
                        .group("Scene");
    app.add_option("--set", sets_,
                   "any scene field: FIELD=VALUE, e.g. --set fill.material.wall_friction=0.05 (repeatable; fields "
                   "as in a scene file; null unsets an optional field); over the scene file, beside the flags")
        .group("Scene");
    // One flag per field that has one (sim/scene/scene_fields.cpp), in scene-file order.
    std::vector<const SceneField*> fields;
    for (const SceneField& f : scene_fields())
        if (!f.flag.empty() && std::find(without.begin(), without.end(), f.path) == without.end())
            fields.push_back(&f);
    for (const SceneField* f : fields) {
        const std::string help = field_help(*f) + default_note(*f);
        switch (f->type) {
            case FieldType::integer: add_flag<int>(app, *f, help); break;
            case FieldType::number:
            case FieldType::optional_number: add_flag<double>(app, *f, help); break;
            case FieldType::seed: add_flag<std::uint64_t>(app, *f, help); break;
            case FieldType::preset:
            case FieldType::choice: add_flag<std::string>(app, *f, help); break;
        }
    }
}

std::pair<std::string, json> parse_set_flag(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError(fmt::format("--set '{}' is not FIELD=VALUE (e.g. --set fill.material.wall_friction=0.05)", text));
    const std::string field = text.substr(0, eq), flag = "--set " + field, value = text.substr(eq + 1);
    sweep::check_scene_field(field, flag);
    const std::vector<json> v = sweep::parse_grid_values(flag, value);
    if (v.size() != 1)
        throw InputError(fmt::format("{}={}: one value (allowed: a single value; polyroll sweep takes lists)", flag, value));
    return {field, v.front()};
}

std::vector<std::pair<std::string, json>> SceneOptions::parsed_sets() const {
    std::vector<std::pair<std::string, json>> out;
    for (const std::string& s : sets_) {
        std::pair<std::string, json> set = parse_set_flag(s);
        const std::string flag = "--set " + set.first;
        if (std::find(without_.begin(), without_.end(), set.first) != without_.end())
            throw InputError(fmt::format("{}: not allowed here (this command sets {} itself)", flag, set.first));
        for (const auto& done : out)
            if (done.first == set.first) throw InputError(fmt::format("{} is given twice (allowed: once)", flag));
        out.push_back(std::move(set));
    }
    return out;
}

void SceneOptions::add_preset_to(flags::Command& app) {
    preset_option_ = app.add_option("--preset", preset_,
                                    "a preset of the window (polyroll presets lists them, with their lanes); the "
                                    "flags given too override it")
                         .group("Scene");
    lane_option_ = app.add_option("--lane", lane_, "which lane of the --preset, 1 to its lane count").group("Scene");
}

SceneLayer SceneOptions::cli_layer() const {
    SceneLayer cli;
    cli.origin = "command line";
    cli.doc = json::object();
    for (const Flag& f : flags_) {
        if (f.option.count() == 0) continue;
        cli.field_labels.emplace_back(f.field, f.option.name());
        node_at(cli.doc, f.field) = f.value();
    }
    for (const std::pair<std::string, json>& set : parsed_sets()) {
        const std::string& field = set.first;
        const auto by_flag = std::find_if(cli.field_labels.begin(), cli.field_labels.end(),
                                          [&field](const auto& label) { return label.first == field; });
        if (by_flag != cli.field_labels.end())
            throw InputError(fmt::format("--set {} and {} both set {} (allowed: one of them)", field, by_flag->second,
                                         field));
        cli.field_labels.emplace_back(field, "--set " + field);
        node_at(cli.doc, field) = set.second;
    }
    return cli;
}

Scene SceneOptions::resolve_lane(const WindowPreset& preset, int k) const {
    return resolve_scene({window_preset_lane(preset, k), cli_layer()});
}

std::vector<Scene> SceneOptions::resolve_lanes() const {
    if (preset_option_.count() == 0) return {resolve()};
    if (scene_option_.count() > 0)
        throw InputError(fmt::format("--scene {} and --preset {}: both name the scene (allowed: one of them)",
                                     scene_file_, preset_));
    const WindowPreset preset = window_preset(preset_);
    if (lane_option_.count() > 0) return {resolve_lane(preset, lane_)};
    std::vector<Scene> lanes;
    for (int k = 1; k <= static_cast<int>(preset.lanes.size()); ++k) lanes.push_back(resolve_lane(preset, k));
    return lanes;
}

Scene SceneOptions::resolve() const {
    if (lane_option_.count() > 0 && preset_option_.count() == 0)
        throw InputError(fmt::format("--lane {}: a lane of a window preset (allowed: with --preset NAME)", lane_));
    if (preset_option_.count() > 0) {
        if (scene_option_.count() > 0)
            throw InputError(fmt::format("--scene {} and --preset {}: both name the scene (allowed: one of them)",
                                         scene_file_, preset_));
        const WindowPreset preset = window_preset(preset_);
        const int n = static_cast<int>(preset.lanes.size());
        if (lane_option_.count() == 0 && n > 1)
            throw InputError(fmt::format("--preset {}: a race of {} lanes; this command runs one (allowed: --lane 1 to "
                                         "{}; polyroll render --preset {} draws them all side by side)",
                                         preset_, n, n, preset_));
        return resolve_lane(preset, lane_option_.count() > 0 ? lane_ : 1);
    }
    std::vector<SceneLayer> layers;
    if (scene_option_.count() > 0) layers.push_back(read_scene_file(scene_file_));
    layers.push_back(cli_layer());
    return resolve_scene(layers);
}

}  // namespace polyroll::cli
