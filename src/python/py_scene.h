// Scenes from Python arguments, through the command line's field table, validation and messages: a
// scene file or a scene document (dict) first, then keyword arguments named as the scene flags
// (sides=8 for --sides, vertex_radius= for --vertex-radius), then FIELD=VALUE pairs as --set takes
// them ({"fill.material.wall_friction": 0.05}). A bad value raises ValueError with the CLI's line.
#pragma once

#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "sim/scene/scene.h"
#include "sim/scene/scene_json.h"

namespace polyroll::python {

// The layers over the defaults: `source` (None, a path, or a dict), `fields` (keyword -> value) and
// `sets` (field path -> value).
std::vector<SceneLayer> scene_layers(pybind11::handle source, const pybind11::dict& fields, const pybind11::dict& sets);

Scene resolve(pybind11::handle source, const pybind11::dict& fields, const pybind11::dict& sets);

// The scene flag a keyword names ("vertex_radius" -> "--vertex-radius"), or "" for none.
std::string flag_of_keyword(const std::string& keyword);

// Every scene keyword with its field and help: the module's scene_keywords().
pybind11::list keyword_table();

}  // namespace polyroll::python
