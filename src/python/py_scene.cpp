// Scenes from Python arguments: see py_scene.h.
#include "python/py_scene.h"

#include <algorithm>

#include <fmt/core.h>

#include "python/py_json.h"
#include "sim/errors.h"
#include "sim/scene/json_path.h"
#include "sim/scene/scene_fields.h"
#include "sweep/sweep_plan.h"

namespace py = pybind11;

namespace polyroll::python {

using json = nlohmann::ordered_json;

namespace {

std::string keyword_of(std::string_view flag) {
    std::string k(flag.substr(2));  // "--vertex-radius" -> "vertex_radius"
    std::replace(k.begin(), k.end(), '-', '_');
    return k;
}

std::string keyword_list() {
    std::string list;
    for (const SceneField& f : scene_fields())
        if (!f.flag.empty()) list += (list.empty() ? "" : ", ") + keyword_of(f.flag);
    return list;
}

const SceneField* field_of_keyword(const std::string& keyword) {
    for (const SceneField& f : scene_fields())
        if (!f.flag.empty() && keyword_of(f.flag) == keyword) return &f;
    return nullptr;
}

bool is_path(py::handle h) {
    return py::isinstance<py::str>(h) || py::hasattr(h, "__fspath__");
}

}  // namespace

std::string flag_of_keyword(const std::string& keyword) {
    const SceneField* f = field_of_keyword(keyword);
    return f ? std::string(f->flag) : std::string();
}

std::vector<SceneLayer> scene_layers(py::handle source, const py::dict& fields, const py::dict& sets) {
    std::vector<SceneLayer> layers;
    if (is_path(source)) {
        layers.push_back(read_scene_file(py::str(py::module_::import("os").attr("fspath")(source)).cast<std::string>()));
    } else if (py::isinstance<py::dict>(source)) {
        json doc = to_json(source, "scene");
        layers.push_back(SceneLayer{std::move(doc), "the scene dict", {}});
    } else if (!source.is_none()) {
        throw InputError(fmt::format("scene: a {} is not a scene (allowed: None, a scene file's path or a scene dict)",
                                     py::type::of(source).attr("__name__").cast<std::string>()));
    }
    // The keyword arguments and the sets are the command line's flags and --set, in the same words.
    SceneLayer args;
    args.origin = "command line";
    args.doc = json::object();
    for (const auto& [key, value] : fields) {
        const std::string keyword = key.cast<std::string>();
        const SceneField* f = field_of_keyword(keyword);
        if (f == nullptr)
            throw InputError(fmt::format("{}=: not a scene keyword (allowed: {}; any field with set={{\"FIELD\": "
                                         "VALUE}})",
                                         keyword, keyword_list()));
        if (value.is_none()) continue;  // run(sides=None) leaves the field as it is
        node_at(args.doc, std::string(f->path)) = to_json(value, std::string(f->flag));
        args.field_labels.emplace_back(std::string(f->path), std::string(f->flag));
    }
    for (const auto& [key, value] : sets) {
        const std::string field = key.cast<std::string>(), flag = "--set " + field;
        sweep::check_scene_field(field, flag);
        const auto by_flag = std::find_if(args.field_labels.begin(), args.field_labels.end(),
                                          [&field](const auto& label) { return label.first == field; });
        if (by_flag != args.field_labels.end())
            throw InputError(fmt::format("--set {} and {} both set {} (allowed: one of them)", field, by_flag->second,
                                         field));
        node_at(args.doc, field) = to_json(value, flag);
        args.field_labels.emplace_back(field, flag);
    }
    layers.push_back(std::move(args));
    return layers;
}

Scene resolve(py::handle source, const py::dict& fields, const py::dict& sets) {
    return resolve_scene(scene_layers(source, fields, sets));
}

py::list keyword_table() {
    py::list out;
    for (const SceneField& f : scene_fields()) {
        if (f.flag.empty()) continue;
        py::dict row;
        row["keyword"] = keyword_of(f.flag);
        row["field"] = std::string(f.path);
        row["flag"] = std::string(f.flag);
        row["help"] = field_help(f);
        out.append(row);
    }
    return out;
}

}  // namespace polyroll::python
