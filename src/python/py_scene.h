// Scenes from Python arguments, through the command line's field table, validation and messages: a
// scene file or a scene document (dict) first, then keyword arguments named as the scene flags
// (sides=8 for --sides, vertex_radius= for --vertex-radius), then FIELD: VALUE pairs as --set takes
// them (fields={"fill.material.wall_friction": 0.05}). A bad value raises ValueError with the CLI's
// line, naming the keyword as the caller wrote it ("(from sides=2)" where the CLI says "(from --sides)");
// an argument of the wrong kind raises TypeError. None is JSON's null: the value "none" of an optional
// field, refused by the others (the package checks types before they get here).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <pybind11/pybind11.h>

#include "sim/scene/scene.h"
#include "sim/scene/scene_json.h"

namespace polyroll::python {

// The layers over the defaults: `source` (None, a path, or a dict), `keywords` (keyword -> value) and
// `sets` (field path -> value), which messages call `sets_name` (the argument the caller used:
// "fields", or the deprecated "set").
std::vector<SceneLayer> scene_layers(pybind11::handle source, const pybind11::dict& keywords, const pybind11::dict& sets,
                                     const std::string& sets_name = "fields");

Scene resolve(pybind11::handle source, const pybind11::dict& keywords, const pybind11::dict& sets,
              const std::string& sets_name = "fields");

// A window preset's lane as the first layer, for preset= and lane= (`lane` None: the preset's only
// lane). ValueError (InputError) naming the argument as written for an unknown name, a lane out of
// range, or a race without lane=.
SceneLayer preset_lane_layer(const std::string& preset, pybind11::handle lane);

// The window's presets: a list of dicts with name, description and lanes (each lane's resolved scene
// document).
pybind11::list window_preset_table();

// The scene flag a keyword names ("vertex_radius" -> "--vertex-radius"), or "" for none.
std::string flag_of_keyword(const std::string& keyword);

// The keyword of a scene flag ("--vertex-radius" -> "vertex_radius").
std::string keyword_of_flag(std::string_view flag);

// Every scene keyword with its field, flag, type, whether sweep() sweeps it, and help: the module's scene_keywords().
pybind11::list keyword_table();

// Every scene field's type ("integer", "number", "optional_number", "seed", "preset", "choice") by
// its path: what the package checks a value's Python type against.
pybind11::dict field_types();

}  // namespace polyroll::python
