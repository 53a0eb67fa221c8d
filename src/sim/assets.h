// The files of assets/, compiled into the program (src/embed_assets.cmake), and their presets.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace polyroll::assets {

struct EmbeddedFile {
    std::string_view name;  // file name in assets/, e.g. "materials.json"
    std::string_view text;
};
const std::vector<EmbeddedFile>& embedded_files();

// The parsed asset file `name` (e.g. "polygons.json"); throws if it is not bundled.
const nlohmann::ordered_json& file(std::string_view name);

// Preset kinds and the file holding each.
enum class Kind { polygon, material, ramp, fidelity };
std::string_view kind_file(Kind kind);
std::string_view kind_label(Kind kind);  // "polygon", "material", ...

std::vector<std::string> preset_names(Kind kind);
// The preset's "values" object; throws InputError naming the choices if `name` is unknown.
const nlohmann::ordered_json& preset_values(Kind kind, const std::string& name);
const nlohmann::ordered_json& preset_entry(Kind kind, const std::string& name);

// The default scene (assets/defaults.json, "scene").
const nlohmann::ordered_json& default_scene_json();

}  // namespace polyroll::assets
