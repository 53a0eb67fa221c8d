// Scene JSON: layering presets and overrides, type checks, and the resolved form. See scene_json.h.
#include "sim/scene/scene_json.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <type_traits>
#include <variant>
#include <sstream>

#include <fmt/core.h>

#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/scene/json_path.h"
#include "sim/message_text.h"
#include "sim/scene/scene_fields.h"
#include "sim/scene/scene_names.h"
#include "sim/scene/scene_validate.h"

namespace polyroll {
namespace {

using json = nlohmann::ordered_json;


// The sections of a scene file, from the field table: their paths, preset kinds and keys.
struct Section {
    std::string path;                  // "shell", "fill", "fill.material"
    std::optional<assets::Kind> kind;  // sections that may name a preset
    std::vector<std::string> keys;     // field keys and subsection names, in file order (not "preset")
};

std::vector<Section> make_sections() {
    std::vector<Section> sections;
    auto find = [&](std::string_view path) -> Section& {
        for (Section& sec : sections)
            if (sec.path == path) return sec;
        sections.push_back({std::string(path), std::nullopt, {}});
        // A subsection is a key of its parent.
        if (const std::string_view parent = section_of(path); !parent.empty()) {
            Section* p = nullptr;
            for (Section& sec : sections)
                if (sec.path == parent) p = &sec;
            if (p == nullptr) throw std::logic_error("scene fields: a subsection before its section");
            p->keys.emplace_back(key_of(path));
        }
        return sections.back();
    };
    for (const SceneField& f : scene_fields()) {
        const std::string_view parent = section_of(f.path);
        if (const std::string_view grand = section_of(parent); !grand.empty()) find(grand);
        Section& sec = find(parent);
        if (f.type == FieldType::preset) sec.kind = f.kind;
        else sec.keys.emplace_back(key_of(f.path));
    }
    return sections;
}

const std::vector<Section>& sections() {
    static const std::vector<Section> all = make_sections();
    return all;
}

const Section* section_at(std::string_view path) {
    for (const Section& sec : sections())
        if (sec.path == path) return &sec;
    return nullptr;
}

// The top-level sections, in file order: shell, fill, ramp, release, fidelity, run.
std::vector<std::string> top_sections() {
    std::vector<std::string> top;
    for (const Section& sec : sections())
        if (section_of(sec.path).empty()) top.push_back(sec.path);
    return top;
}

// A value as it appears in a message: JSON text, short, and never throwing on strings that are not
// UTF-8 (a command-line flag can hold any bytes; dump() would throw on them).
std::string shown(const json& v) {
    // dump() writes NaN and infinity as null; say what they are (they come from flags: --angle nan).
    if (v.is_number_float() && !std::isfinite(v.get<double>())) return fmt::format("{}", v.get<double>());
    std::string s = v.dump(-1, ' ', false, json::error_handler_t::replace);
    if (s.size() > 80) s = s.substr(0, 77) + "...";
    return s;
}

// Where each resolved field came from, for messages.
using Origins = std::map<std::string, std::string>;

class Resolver {
public:
    Resolver() {
        for (const Section& sec : sections()) values_[sec.path] = json::object();
        const SceneLayer defaults{assets::default_scene_json(), "assets/defaults.json", {}};
        apply(defaults);
        layer_ = nullptr;  // `defaults` dies here: no pointer to it may outlive the constructor
    }

    void apply(const SceneLayer& layer) {
        layer_ = &layer;
        if (!layer.doc.is_object())
            throw InputError(fmt::format("{}: a scene must be a JSON object", layer.origin));
        const std::vector<std::string> top = top_sections();
        for (const auto& [key, value] : layer.doc.items()) {
            if (key == "description") {  // free text for the file's author
                if (!value.is_string())
                    throw InputError(fmt::format("{}: description is {} (allowed: a text in quotes)", layer.origin,
                                                 value.dump()));
                continue;
            }
            if (key == "scene" || key == "results")
                throw InputError(fmt::format(
                    "{}: unknown key '{}' (a summary.json is not a scene; use its \"scene\" object as the file)",
                    layer.origin, key));
            if (std::find(top.begin(), top.end(), key) == top.end())
                throw InputError(
                    fmt::format("{}: unknown key '{}' (allowed: {}, description)", layer.origin, key, comma_list(top)));
        }
        for (const std::string& name : top)
            if (layer.doc.contains(name)) section(layer.doc.at(name), *section_at(name));
    }

    Scene scene() const {
        Scene s;
        for (const SceneField& f : scene_fields()) f.access.set(s, value_of(f));
        validate_scene(s, [this](const std::string& field) { return where(field); });
        return s;
    }

private:
    std::string label(const std::string& field) const {
        for (const auto& [f, flag] : layer_->field_labels)
            if (f == field) return flag;
        return layer_->origin;
    }

    std::string where(const std::string& field) const {
        auto it = origins_.find(field);
        if (it == origins_.end()) return "";
        return fmt::format(" (from {})", it->second);
    }

    // Applies one section's value: a preset name, or an object with an optional "preset", its
    // fields' values and its subsections.
    void section(const json& given, const Section& sec) {
        const std::string& path = sec.path;
        json value = given;
        if (value.is_string() && sec.kind) value = json{{"preset", value}};
        if (!value.is_object()) {
            // A section without presets says which keys it holds (fill: ratio, material).
            throw InputError(fmt::format("{}: {} must be {}, got {}", layer_->origin, path,
                                         sec.kind ? "a preset name or an object"
                                                  : fmt::format("an object with keys {}", comma_list(sec.keys)),
                                         shown(value)));
        }
        json& out = values_.at(path);
        if (value.contains("preset")) {
            if (!sec.kind)
                throw InputError(fmt::format("{}: unknown key '{}.preset' (allowed: {})", layer_->origin, path,
                                             comma_list(sec.keys)));
            const json& p = value.at("preset");
            if (!p.is_string())
                throw InputError(fmt::format("{}: {}.preset must be a preset name, got {}", layer_->origin, path,
                                             shown(p)));
            const std::string preset = p.get<std::string>();
            try {
                for (const auto& [k, v] : assets::preset_values(*sec.kind, preset).items()) {
                    out[k] = v;
                    origins_[path + "." + k] = fmt::format("{} preset '{}'", assets::kind_label(*sec.kind), preset);
                }
            } catch (const InputError& e) {
                throw InputError(fmt::format("{}: {}", label(path + ".preset"), e.what()));
            }
            out["preset"] = preset;
        }
        for (const auto& [k, v] : value.items()) {
            if (k == "preset") continue;
            if (std::find(sec.keys.begin(), sec.keys.end(), k) == sec.keys.end()) {
                // fill.grains_per_disc (one release's name) became a material's value: say where it went.
                const bool moved = path == "fill" && k == "grains_per_disc";
                throw InputError(fmt::format("{}: unknown key '{}.{}' ({}allowed: {}{})", layer_->origin, path, k,
                                             moved ? "it moved to fill.material.grains_per_disc; " : "",
                                             sec.kind ? "preset, " : "", comma_list(sec.keys)));
            }
            if (const Section* sub = section_at(path + "." + k)) {
                section(v, *sub);
                continue;
            }
            out[k] = v;
            origins_[path + "." + k] = label(path + "." + k);
        }
    }

    // The field's resolved value, checked for its type (its range is validate_scene's).
    FieldValue value_of(const SceneField& f) const {
        const std::string field(f.path);
        const json& sec = values_.at(std::string(section_of(f.path)));
        const std::string key(key_of(f.path));
        if (f.type == FieldType::preset) return sec.value("preset", "");
        if (!sec.contains(key)) {  // only when a replaced asset file leaves a field out
            const std::string preset = sec.value("preset", "");
            throw InputError(
                preset.empty()
                    ? fmt::format("{} is not set (assets/defaults.json must give every field)", field)
                    : fmt::format("{} is not set: preset '{}' does not give it, nor does assets/defaults.json "
                                  "(an asset file from an older version? add the field to the preset)",
                                  field, preset));
        }
        const json& v = sec.at(key);
        switch (f.type) {
            case FieldType::integer: return integer(v, field);
            case FieldType::number: return number(v, field);
            case FieldType::optional_number: return v.is_null() ? std::nullopt : std::optional(number(v, field));
            case FieldType::seed:
                // 7.0 as 7, as for the other whole-number fields; only below 2^53, where a double is exact.
                if (v.is_number_float() && v.get<double>() >= 0.0 && v.get<double>() < 9007199254740992.0 &&
                    v.get<double>() == std::floor(v.get<double>()))
                    return static_cast<std::uint64_t>(v.get<double>());
                if (!v.is_number_unsigned())
                    throw InputError(fmt::format("{} = {}{} must be a whole number from 0 to 2^64-1", field, shown(v),
                                                 where(field)));
                return v.get<std::uint64_t>();
            case FieldType::choice: return choice(f, v);
            case FieldType::preset: break;
        }
        return {};
    }

    FieldValue choice(const SceneField& f, const json& v) const {
        const std::string field(f.path);
        if (v.is_string() && f.choice_named)
            if (auto value = f.choice_named(v.get<std::string>())) return *value;
        throw InputError(fmt::format("{} = {}{} is not allowed (allowed: {})", field, shown(v), where(field),
                                     comma_list(field_choices(f))));
    }

    double number(const json& v, const std::string& field) const {
        if (!v.is_number())
            throw InputError(fmt::format("{} = {}{} must be a number", field, shown(v), where(field)));
        const double d = v.get<double>();
        if (!std::isfinite(d))
            throw InputError(fmt::format("{} = {}{} must be a finite number", field, shown(v), where(field)));
        return d;
    }
    int integer(const json& v, const std::string& field) const {
        // 6.0 is a whole number: JSON has one number type, and tools writing scene files (Python's json,
        // spreadsheets) write 6.0 for 6. A fractional part is refused.
        const bool whole_float = v.is_number_float() && std::isfinite(v.get<double>()) &&
                                 v.get<double>() == std::floor(v.get<double>());
        if (!v.is_number_integer() && !whole_float)
            throw InputError(fmt::format("{} = {}{} must be a whole number", field, shown(v), where(field)));
        if (whole_float && std::abs(v.get<double>()) > 1e9)
            throw InputError(fmt::format("{} = {}{} is far out of range", field, shown(v), where(field)));
        const auto i = whole_float ? static_cast<std::int64_t>(v.get<double>()) : v.get<std::int64_t>();
        if (i < -1000000000 || i > 1000000000)
            throw InputError(fmt::format("{} = {}{} is far out of range", field, shown(v), where(field)));
        return static_cast<int>(i);
    }

    const SceneLayer* layer_ = nullptr;
    std::map<std::string, json> values_;  // each section's resolved values, by its path
    Origins origins_;
};

}  // namespace

SceneLayer read_scene_file(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw InputError(fmt::format("scene file {}: is a directory, expected a JSON file", name));
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(fmt::format("scene file {}: {}", name, open_failure_reason(errno)));
    // Read at most one byte past the cap, so an endless or huge file costs bounded memory and time.
    std::string text;
    char chunk[65536];
    while (text.size() <= kMaxSceneFileBytes && in.read(chunk, sizeof chunk).gcount() > 0)
        text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxSceneFileBytes)
        throw InputError(fmt::format("scene file {}: larger than {} bytes, not a scene file", name, kMaxSceneFileBytes));
    if (in.bad()) throw InputError(fmt::format("scene file {}: cannot be read", name));
    return parse_scene_text(text, name);
}

SceneLayer parse_scene_text(std::string_view text, const std::string& origin) {
    // nlohmann keeps the last of duplicate keys silently; a scene file that says a thing twice is
    // refused instead, naming the key. One set of seen keys per open object, with its path.
    struct Open {
        std::string path;
        std::vector<std::string> keys;
    };
    std::vector<Open> open;
    std::string last_key;
    std::string field;  // the last key read, with its path: where a syntax error is
    constexpr int kMaxDepth = 32;
    auto refuse_duplicates = [&](int depth, json::parse_event_t event, json& parsed) {
        // Copying and printing a value recurse; a scene is four levels deep, so deep nesting is
        // refused before it can exhaust the stack.
        if (depth > kMaxDepth)
            throw InputError(fmt::format("scene file {}: nested deeper than {} levels, not a scene file", origin,
                                         kMaxDepth));
        switch (event) {
            case json::parse_event_t::object_start:
                if (open.empty()) open.push_back({"", {}});
                else open.push_back({open.back().path.empty() ? last_key : open.back().path + "." + last_key, {}});
                break;
            case json::parse_event_t::object_end:
                if (!open.empty()) open.pop_back();
                break;
            case json::parse_event_t::key: {
                last_key = parsed.get<std::string>();
                auto& keys = open.back().keys;
                field = open.back().path.empty() ? last_key : open.back().path + "." + last_key;
                if (std::find(keys.begin(), keys.end(), last_key) != keys.end())
                    throw InputError(printable_line(fmt::format(
                        "scene file {}: duplicate key '{}' (each key may appear once)", origin, field)));
                keys.push_back(last_key);
                break;
            }
            default: break;
        }
        return true;
    };
    SceneLayer layer;
    layer.origin = origin;
    try {
        layer.doc = json::parse(text.begin(), text.end(), refuse_duplicates);
    } catch (const nlohmann::json::exception& e) {
        // A syntax error, or a number too large for a double (1e999: out_of_range, not parse_error).
        // nlohmann's message names the byte offset and the token (which may be any bytes): keep it
        // on one printable line.
        throw InputError(printable_line(fmt::format("scene file {}: not valid JSON{}: {}", origin,
                                                    field.empty() ? "" : " after key '" + field + "'",
                                                    json_error_text(e.what()))));
    }
    if (!layer.doc.is_object())
        throw InputError(fmt::format("scene file {}: a scene must be a JSON object", origin));
    return layer;
}

Scene resolve_scene(const std::vector<SceneLayer>& layers) {
    Resolver r;
    for (const SceneLayer& layer : layers) r.apply(layer);
    return r.scene();
}

nlohmann::ordered_json scene_to_json(const Scene& s) {
    json j = json::object();
    for (const SceneField& f : scene_fields()) {
        // Sections appear in the table's order.
        json* node = &node_at(j, section_of(f.path));
        const std::string key(key_of(f.path));
        std::visit(
            [&](const auto& v) {
                using V = std::decay_t<decltype(v)>;
                if constexpr (std::is_same_v<V, std::string>) {
                    if (!v.empty()) (*node)[key] = v;  // a preset name only when there is one
                } else if constexpr (std::is_same_v<V, std::optional<double>>) {
                    (*node)[key] = v ? json(*v) : json(nullptr);
                } else if constexpr (std::is_same_v<V, ReleasePose> || std::is_same_v<V, Model> || std::is_same_v<V, EngineFrame> || std::is_same_v<V, GrainContacts>) {
                    (*node)[key] = to_string(v);
                } else {
                    (*node)[key] = v;
                }
            },
            f.access.get(s));
    }
    return j;
}

}  // namespace polyroll
