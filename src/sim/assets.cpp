// Access to the asset files, bundled or replaced from a folder: see assets.h.
#include "sim/assets.h"

#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "sim/errors.h"
#include "sim/message_text.h"

namespace polyroll::assets {

namespace {

using json = nlohmann::ordered_json;

// One lock for the folder and the parsed files; parsed files are never freed, so the references
// file() hands out stay valid whatever folder is chosen later.
std::mutex& lock() {
    static std::mutex mutex;
    return mutex;
}

std::filesystem::path& chosen_directory() {
    static std::filesystem::path dir = [] {
        const char* env = std::getenv(kDirectoryVariable);
        return env ? std::filesystem::path(env) : std::filesystem::path();
    }();
    return dir;
}

std::string_view bundled_text(std::string_view name) {
    for (const EmbeddedFile& f : embedded_files())
        if (f.name == name) return f.text;
    throw std::logic_error(fmt::format("asset file {} is not bundled", name));
}

// The replacement for `name` in `dir`, parsed; nothing if the folder has no such file.
std::optional<json> replacement(const std::filesystem::path& dir, std::string_view name) {
    if (dir.empty()) return std::nullopt;
    const std::filesystem::path path = dir / std::string(name);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) throw InputError(fmt::format("{} {}: cannot be read", kDirectoryVariable, path.string()));
    try {
        return json::parse(text.str());
    } catch (const json::exception& e) {
        throw InputError(
            printable_line(fmt::format("{} {}: not valid JSON: {}", kDirectoryVariable, path.string(),
                                       json_error_text(e.what()))));
    }
}

const json& file_locked(std::string_view name) {
    static std::map<std::string, json, std::less<>> parsed;  // by folder and name
    const std::filesystem::path& dir = chosen_directory();
    const std::string key = dir.string() + "|" + std::string(name);
    if (auto it = parsed.find(key); it != parsed.end()) return it->second;
    std::optional<json> doc = replacement(dir, name);
    // Bundled files are checked by the tests; a parse error there is a build defect.
    if (!doc) doc = json::parse(bundled_text(name));
    return parsed.emplace(key, std::move(*doc)).first->second;
}

std::array<int, 3> rgb_of(const json& look) {
    const json& rgb = look.at("rgb");
    return {rgb.at(0).get<int>(), rgb.at(1).get<int>(), rgb.at(2).get<int>()};
}

}  // namespace

std::filesystem::path directory() {
    std::lock_guard guard(lock());
    return chosen_directory();
}

void use_directory(const std::filesystem::path& dir) {
    std::lock_guard guard(lock());
    chosen_directory() = dir;
}

const nlohmann::ordered_json& file(std::string_view name) {
    std::lock_guard guard(lock());
    return file_locked(name);
}

MaterialLook material_look(const std::string& preset) {
    const json& materials = file(kind_file(Kind::material));
    const json& presets = materials.at("presets");
    if (auto it = presets.find(preset); it != presets.end() && it->contains("look")) {
        const json& look = it->at("look");
        return {look.at("label").get<std::string>(), rgb_of(look)};
    }
    const json& custom = materials.at("custom_look");
    return {preset.empty() ? custom.at("label").get<std::string>() : preset, rgb_of(custom)};
}

std::string_view kind_file(Kind kind) {
    switch (kind) {
        case Kind::polygon: return "polygons.json";
        case Kind::material: return "materials.json";
        case Kind::ramp: return "ramps.json";
        case Kind::fidelity: return "fidelity.json";
        case Kind::closure: return "closures.json";
    }
    return "";
}

std::string_view kind_label(Kind kind) {
    switch (kind) {
        case Kind::polygon: return "polygon";
        case Kind::material: return "material";
        case Kind::ramp: return "ramp";
        case Kind::fidelity: return "fidelity";
        case Kind::closure: return "closure";
    }
    return "";
}

const std::vector<Kind>& all_kinds() {
    static const std::vector<Kind> kinds = {Kind::polygon, Kind::material, Kind::ramp, Kind::fidelity, Kind::closure};
    return kinds;
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
