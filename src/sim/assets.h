// The files of assets/, compiled into the program (src/embed_assets.cmake), and their presets. A
// folder named by the environment variable POLYROLL_ASSETS may replace any of them at run time: a
// file there (e.g. materials.json with a fourth material) is read instead of the bundled one.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace polyroll::assets {

struct EmbeddedFile {
    std::string_view name;  // file name in assets/, e.g. "materials.json"
    std::string_view text;
};
const std::vector<EmbeddedFile>& embedded_files();

// The environment variable naming a folder of replacement asset files.
inline constexpr const char* kDirectoryVariable = "POLYROLL_ASSETS";

// The folder whose files replace the bundled ones: $POLYROLL_ASSETS when first asked, or what
// use_directory() set last; empty for none.
std::filesystem::path directory();
// Reads asset files from `dir` (empty: the bundled files only) from now on; for tests, which
// switch folders within one process. Files already read stay valid.
void use_directory(const std::filesystem::path& dir);

// The parsed asset file `name` (e.g. "polygons.json"): the replacement folder's copy if it has one,
// else the bundled one. Throws InputError for a replacement that is not valid JSON, logic_error for
// a name that is not bundled.
const nlohmann::ordered_json& file(std::string_view name);

// Preset kinds and the file holding each.
enum class Kind { polygon, material, ramp, fidelity, closure };
// Every kind, in the order files and listings show them.
const std::vector<Kind>& all_kinds();
std::string_view kind_file(Kind kind);
std::string_view kind_label(Kind kind);  // "polygon", "material", ...

std::vector<std::string> preset_names(Kind kind);
// The preset's "values" object; throws InputError naming the choices if `name` is unknown.
const nlohmann::ordered_json& preset_values(Kind kind, const std::string& name);
const nlohmann::ordered_json& preset_entry(Kind kind, const std::string& name);

// How a material preset is shown (materials.json, "look"): its label and its grains' colour.
struct MaterialLook {
    std::string label;        // "BBs"
    std::array<int, 3> rgb{};  // 8-bit RGB
};
// A preset's look; "" (grains of the scene's own) and names that are no preset get the file's
// "custom_look" colour, and their own name as the label if they have one.
MaterialLook material_look(const std::string& preset);

// The default scene (assets/defaults.json, "scene").
const nlohmann::ordered_json& default_scene_json();

}  // namespace polyroll::assets
