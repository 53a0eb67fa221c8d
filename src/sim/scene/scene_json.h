// Reading and writing scenes as JSON. A scene document has the sections shell, fill, ramp, release,
// fidelity and run; a section may name a preset ("preset": "hexagon-small", or just the name as a
// string) and override any of its values. Layers apply in order over assets/defaults.json.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/scene/scene.h"
#include "sim/scene/scene_names.h"  // to_string of the enums, for the files that name them

namespace polyroll {

struct SceneLayer {
    nlohmann::ordered_json doc;
    std::string origin;  // names the layer in messages: a file name, or "command line"
    // For the command line: the flag that set a field ("shell.sides" -> "--sides").
    std::vector<std::pair<std::string, std::string>> field_labels;
};

// Reads and parses a scene file; throws InputError (unreadable, not a regular file, larger than
// kMaxSceneFileBytes, not JSON, a duplicate key, not an object).
SceneLayer read_scene_file(const std::filesystem::path& path);

// Parses a scene document's text; `origin` names it in messages. Throws InputError as above.
SceneLayer parse_scene_text(std::string_view text, const std::string& origin);

// Scene files are a few kilobytes; the cap keeps memory bounded when pointed at something huge or
// endless (/dev/zero, a log file).
inline constexpr std::size_t kMaxSceneFileBytes = 1 << 20;

// The defaults, then each layer in order; checks keys and types, then validates ranges
// (scene_validate.h). Throws InputError naming the field, its value and what is allowed.
Scene resolve_scene(const std::vector<SceneLayer>& layers);

// The fully resolved scene in the same format: feeding it back resolves to the same Scene.
nlohmann::ordered_json scene_to_json(const Scene& scene);

}  // namespace polyroll
