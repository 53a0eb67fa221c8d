// Access to the embedded asset files: see assets.h.
#include "sim/assets.h"

#include <map>
#include <mutex>

#include <fmt/format.h>

#include "sim/errors.h"

namespace polyroll::assets {

const nlohmann::ordered_json& file(std::string_view name) {
    static std::mutex mutex;
    static std::map<std::string, nlohmann::ordered_json, std::less<>> parsed;
    std::lock_guard lock(mutex);
    if (auto it = parsed.find(name); it != parsed.end()) return it->second;
    for (const EmbeddedFile& f : embedded_files()) {
        if (f.name == name) {
            // Bundled files are checked by the tests; a parse error here is a build defect.
            return parsed.emplace(std::string(name), nlohmann::ordered_json::parse(f.text)).first->second;
        }
    }
    throw std::logic_error(fmt::format("asset file {} is not bundled", name));
}

std::string_view kind_file(Kind kind) {
    switch (kind) {
        case Kind::polygon: return "polygons.json";
        case Kind::material: return "materials.json";
        case Kind::ramp: return "ramps.json";
        case Kind::fidelity: return "fidelity.json";
    }
    return "";
}

std::string_view kind_label(Kind kind) {
    switch (kind) {
        case Kind::polygon: return "polygon";
        case Kind::material: return "material";
        case Kind::ramp: return "ramp";
        case Kind::fidelity: return "fidelity";
    }
    return "";
}

std::vector<std::string> preset_names(Kind kind) {
    std::vector<std::string> names;
    for (const auto& [name, entry] : file(kind_file(kind)).at("presets").items()) names.push_back(name);
    return names;
}

const nlohmann::ordered_json& preset_entry(Kind kind, const std::string& name) {
    const auto& presets = file(kind_file(kind)).at("presets");
    if (auto it = presets.find(name); it != presets.end()) return *it;
    std::string allowed;
    for (const std::string& n : preset_names(kind)) allowed += (allowed.empty() ? "" : ", ") + n;
    throw InputError(fmt::format("unknown {} preset '{}' (allowed: {})", kind_label(kind), name, allowed));
}

const nlohmann::ordered_json& preset_values(Kind kind, const std::string& name) {
    return preset_entry(kind, name).at("values");
}

const nlohmann::ordered_json& default_scene_json() { return file("defaults.json").at("scene"); }

}  // namespace polyroll::assets
