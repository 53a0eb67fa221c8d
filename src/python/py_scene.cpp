// Scenes from Python arguments: see py_scene.h.
#include "python/py_scene.h"

#include <algorithm>

#include <fmt/core.h>

#include "python/py_json.h"
#include "sim/errors.h"
#include "sim/scene/json_path.h"
#include "sim/scene/scene_fields.h"
#include "sim/scene/window_presets.h"
#include "sweep/sweep_plan.h"

namespace py = pybind11;

namespace polyroll::python {

using json = nlohmann::ordered_json;

namespace {

std::string keyword_list() {
    std::string list;
    for (const SceneField& f : scene_fields())
        if (!f.flag.empty()) list += (list.empty() ? "" : ", ") + keyword_of_flag(f.flag);
    return list;
}

const SceneField* field_of_keyword(const std::string& keyword) {
    for (const SceneField& f : scene_fields())
        if (!f.flag.empty() && keyword_of_flag(f.flag) == keyword) return &f;
    return nullptr;
}

const char* type_name(FieldType t) {
    switch (t) {
        case FieldType::integer: return "integer";
        case FieldType::number: return "number";
        case FieldType::optional_number: return "optional_number";
        case FieldType::seed: return "seed";
        case FieldType::preset: return "preset";
        case FieldType::choice: return "choice";
    }
    return "";
}

bool is_path(py::handle h) {
    return py::isinstance<py::str>(h) || py::hasattr(h, "__fspath__");
}

}  // namespace

std::string keyword_of_flag(std::string_view flag) {
    std::string k(flag.substr(2));  // "--vertex-radius" -> "vertex_radius"
    std::replace(k.begin(), k.end(), '-', '_');
    return k;
}

std::string flag_of_keyword(const std::string& keyword) {
    const SceneField* f = field_of_keyword(keyword);
    return f ? std::string(f->flag) : std::string();
}

std::vector<SceneLayer> scene_layers(py::handle source, const py::dict& keywords, const py::dict& sets,
                                     const std::string& sets_name) {
    std::vector<SceneLayer> layers;
    if (is_path(source)) {
        layers.push_back(read_scene_file(py::str(py::module_::import("os").attr("fspath")(source)).cast<std::string>()));
    } else if (py::isinstance<py::dict>(source)) {
        json doc = to_json(source, "scene");
        layers.push_back(SceneLayer{std::move(doc), "the scene dict", {}});
    } else if (!source.is_none()) {
        throw py::type_error(fmt::format("scene: {} is not a scene (allowed: None, a scene file's path or a scene dict)",
                                         a_type_name(source)));
    }
    // The keywords and the sets are the command line's flags and --set, in the same words; messages
    // name them as the caller wrote them: "(from sides=2)", "(from fields["ramp.length_m"])".
    SceneLayer args;
    args.origin = "the keywords";
    args.doc = json::object();
    for (const auto& [key, value] : keywords) {
        const std::string keyword = key.cast<std::string>();
        const SceneField* f = field_of_keyword(keyword);
        if (f == nullptr)
            throw py::type_error(fmt::format("unexpected keyword argument '{}' (allowed: {}; any field with "
                                             "fields={{\"FIELD\": VALUE}})",
                                             keyword, keyword_list()));
        const std::string label = keyword + "=" + py::repr(value).cast<std::string>();  // "sides=2"
        node_at(args.doc, std::string(f->path)) = to_json(value, label);
        args.field_labels.emplace_back(std::string(f->path), label);
    }
    for (const auto& [key, value] : sets) {
        const std::string field = key.cast<std::string>(), label = fmt::format("{}[\"{}\"]", sets_name, field);
        sweep::check_scene_field(field, label);
        const auto by_keyword = std::find_if(args.field_labels.begin(), args.field_labels.end(),
                                             [&field](const auto& l) { return l.first == field; });
        if (by_keyword != args.field_labels.end())
            throw InputError(fmt::format("{} and {} both set {} (allowed: one of them)", label, by_keyword->second, field));
        node_at(args.doc, field) = to_json(value, label);
        args.field_labels.emplace_back(field, label);
    }
    layers.push_back(std::move(args));
    return layers;
}

Scene resolve(py::handle source, const py::dict& keywords, const py::dict& sets, const std::string& sets_name) {
    return resolve_scene(scene_layers(source, keywords, sets, sets_name));
}

SceneLayer preset_lane_layer(const std::string& preset, py::handle lane) {
    const std::string said = "preset=" + py::repr(py::str(preset)).cast<std::string>();
    const WindowPreset p = window_preset(preset, said);
    const int n = static_cast<int>(p.lanes.size());
    if (lane.is_none()) {
        if (n > 1)
            throw InputError(fmt::format("{}: a race of {} lanes; a run takes one (allowed: lane=1 to {}; polyroll "
                                         "render --preset {} draws them all side by side)",
                                         said, n, n, preset));
        return window_preset_lane(p, 1, "lane=1");
    }
    int k = 0;  // out of range unless it fits
    try {
        k = lane.cast<int>();
    } catch (const py::cast_error&) {
    }
    return window_preset_lane(p, k, "lane=" + py::repr(lane).cast<std::string>());
}

py::list window_preset_table() {
    py::list out;
    for (const std::string& name : window_preset_names()) {
        const WindowPreset p = window_preset(name);
        py::dict row;
        row["name"] = name;
        row["description"] = p.description;
        py::list lanes;
        for (const Scene& scene : resolve_window_preset(p)) lanes.append(from_json(scene_to_json(scene)));
        row["lanes"] = lanes;
        out.append(row);
    }
    return out;
}

py::list keyword_table() {
    py::list out;
    for (const SceneField& f : scene_fields()) {
        if (f.flag.empty()) continue;
        py::dict row;
        row["keyword"] = keyword_of_flag(f.flag);
        row["field"] = std::string(f.path);
        row["flag"] = std::string(f.flag);
        row["type"] = type_name(f.type);
        row["swept"] = f.sweep_axis > 0;  // sweep() takes a grid for it
        row["help"] = field_help(f);
        out.append(row);
    }
    return out;
}

py::dict field_types() {
    py::dict out;
    for (const SceneField& f : scene_fields()) out[py::str(std::string(f.path))] = type_name(f.type);
    return out;
}

}  // namespace polyroll::python
