// Scene JSON: layering presets and overrides, type checks, and the resolved form. See scene_json.h.
#include "sim/scene_json.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <type_traits>
#include <variant>
#include <sstream>

#include <fmt/format.h>

#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/message_text.h"
#include "sim/scene_validate.h"

namespace polyroll {
namespace {

using json = nlohmann::ordered_json;

// Each section's numeric fields, in output order: one table serves reading, writing and the list
// of allowed keys. Fields with their own form (preset names, release.pose, run.model, run.seed)
// are handled by name.
template <class S>
struct Field {
    const char* key;
    std::variant<double S::*, int S::*, std::optional<double> S::*> member;
};
const std::vector<Field<ShellParams>> kShellFields = {
    {"sides", &ShellParams::sides},
    {"inner_circumradius_m", &ShellParams::inner_circumradius_m},
    {"wall_thickness_m", &ShellParams::wall_thickness_m},
    {"depth_m", &ShellParams::depth_m},
    {"lid_thickness_m", &ShellParams::lid_thickness_m},
    {"mass_kg", &ShellParams::mass_kg},
    {"lid_mass_fraction", &ShellParams::lid_mass_fraction}};
const std::vector<Field<MaterialParams>> kMaterialFields = {
    {"diameter_m", &MaterialParams::diameter_m},
    {"diameter_spread", &MaterialParams::diameter_spread},
    {"bulk_density_kg_m3", &MaterialParams::bulk_density_kg_m3},
    {"friction", &MaterialParams::friction},
    {"wall_friction", &MaterialParams::wall_friction},
    {"restitution", &MaterialParams::restitution}};
const std::vector<Field<RampParams>> kRampFields = {{"length_m", &RampParams::length_m},
                                                   {"friction", &RampParams::friction},
                                                   {"restitution", &RampParams::restitution},
                                                   {"angle_deg", &RampParams::angle_deg}};
const std::vector<Field<ReleaseParams>> kReleaseFields = {{"tilt_deg", &ReleaseParams::tilt_deg}};
const std::vector<Field<FidelityParams>> kFidelityFields = {
    {"step_hz", &FidelityParams::step_hz},
    {"substeps", &FidelityParams::substeps},
    {"velocity_iterations", &FidelityParams::velocity_iterations},
    {"position_iterations", &FidelityParams::position_iterations}};
const std::vector<Field<RunParams>> kRunFields = {{"time_limit_s", &RunParams::time_limit_s},
                                                  {"sample_hz", &RunParams::sample_hz},
                                                  {"gravity_m_s2", &RunParams::gravity_m_s2},
                                                  {"settle_time_s", &RunParams::settle_time_s},
                                                  {"rest_speed_m_s", &RunParams::rest_speed_m_s},
                                                  {"rest_time_s", &RunParams::rest_time_s}};

template <class S>
std::vector<std::string> keys_of(const std::vector<Field<S>>& fields, std::vector<std::string> extra = {}) {
    for (const auto& f : fields) extra.emplace_back(f.key);
    return extra;
}
const std::vector<std::string> kShellKeys = keys_of(kShellFields);
const std::vector<std::string> kMaterialKeys = keys_of(kMaterialFields);
const std::vector<std::string> kRampKeys = keys_of(kRampFields);
const std::vector<std::string> kReleaseKeys = keys_of(kReleaseFields, {"pose"});
const std::vector<std::string> kFidelityKeys = keys_of(kFidelityFields);
const std::vector<std::string> kRunKeys = keys_of(kRunFields, {"model", "seed"});

template <class S>
void write_fields(json& out, const S& params, const std::vector<Field<S>>& fields) {
    for (const auto& f : fields) {
        std::visit(
            [&](auto member) {
                const auto& v = params.*member;
                if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::optional<double>>)
                    out[f.key] = v ? json(*v) : json(nullptr);
                else
                    out[f.key] = v;
            },
            f.member);
    }
}
const std::vector<std::string> kSections = {"shell", "fill", "ramp", "release", "fidelity", "run"};

// A value as it appears in a message: JSON text, short, and never throwing on strings that are not
// UTF-8 (a command-line flag can hold any bytes; dump() would throw on them).
std::string shown(const json& v) {
    // dump() writes NaN and infinity as null; say what they are (they come from flags: --angle nan).
    if (v.is_number_float() && !std::isfinite(v.get<double>())) return fmt::format("{}", v.get<double>());
    std::string s = v.dump(-1, ' ', false, json::error_handler_t::replace);
    if (s.size() > 80) s = s.substr(0, 77) + "...";
    return s;
}

std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
}

// Where each resolved field came from, for messages.
using Origins = std::map<std::string, std::string>;

class Resolver {
public:
    Resolver() {
        const SceneLayer defaults{assets::default_scene_json(), "assets/defaults.json", {}};
        apply(defaults);
        layer_ = nullptr;  // `defaults` dies here: no pointer to it may outlive the constructor
    }

    void apply(const SceneLayer& layer) {
        layer_ = &layer;
        if (!layer.doc.is_object())
            throw InputError(fmt::format("{}: a scene must be a JSON object", layer.origin));
        for (const auto& [key, value] : layer.doc.items()) {
            if (key == "description") continue;  // free text for the file's author
            if (key == "scene" || key == "results")
                throw InputError(fmt::format(
                    "{}: unknown key '{}' (a summary.json is not a scene; use its \"scene\" object as the file)",
                    layer.origin, key));
            if (std::find(kSections.begin(), kSections.end(), key) == kSections.end())
                throw InputError(fmt::format("{}: unknown key '{}' (allowed: {}, description)", layer.origin, key,
                                             join(kSections)));
        }
        section(layer.doc, "shell", assets::Kind::polygon, kShellKeys, shell_);
        section(layer.doc, "ramp", assets::Kind::ramp, kRampKeys, ramp_);
        section(layer.doc, "fidelity", assets::Kind::fidelity, kFidelityKeys, fidelity_);
        section(layer.doc, "release", std::nullopt, kReleaseKeys, release_);
        section(layer.doc, "run", std::nullopt, kRunKeys, run_);
        if (layer.doc.contains("fill")) {
            const json& fill = layer.doc.at("fill");
            if (!fill.is_object())
                throw InputError(fmt::format("{}: fill must be an object with keys ratio, material, got {}",
                                             layer.origin, shown(fill)));
            for (const auto& [key, value] : fill.items()) {
                if (key == "ratio") {
                    fill_ratio_ = value;
                    origins_["fill.ratio"] = label("fill.ratio");
                } else if (key == "material") {
                    section(fill, "material", assets::Kind::material, kMaterialKeys, material_, "fill.");
                } else {
                    throw InputError(
                        fmt::format("{}: unknown key 'fill.{}' (allowed: ratio, material)", layer.origin, key));
                }
            }
        }
    }

    Scene scene() const {
        Scene s;
        s.shell.preset = shell_.value("preset", "");
        read_fields(shell_, "shell", s.shell, kShellFields);
        s.fill.ratio = number_value(fill_ratio_, "fill.ratio");
        s.fill.material.preset = material_.value("preset", "");
        read_fields(material_, "fill.material", s.fill.material, kMaterialFields);
        s.ramp.preset = ramp_.value("preset", "");
        read_fields(ramp_, "ramp", s.ramp, kRampFields);
        read_fields(release_, "release", s.release, kReleaseFields);
        s.fidelity.preset = fidelity_.value("preset", "");
        read_fields(fidelity_, "fidelity", s.fidelity, kFidelityFields);
        read_fields(run_, "run", s.run, kRunFields);

        const json& pose = release_.at("pose");
        if (pose == "vertex") s.release.pose = ReleasePose::vertex;
        else if (pose == "face") s.release.pose = ReleasePose::face;
        else throw InputError(fmt::format("release.pose = {}{} is not allowed (allowed: vertex, face)",
                                          shown(pose), where("release.pose")));

        const json& model = run_.at("model");
        if (model == "grains") s.run.model = Model::grains;
        else if (model == "segments") s.run.model = Model::segments;
        else if (model == "rigid") s.run.model = Model::rigid;
        else throw InputError(fmt::format("run.model = {}{} is not allowed (allowed: grains, segments, rigid)",
                                          shown(model), where("run.model")));

        const json& seed = run_.at("seed");
        if (!seed.is_number_unsigned())
            throw InputError(fmt::format("run.seed = {}{} must be a whole number from 0 to 2^64-1", shown(seed),
                                         where("run.seed")));
        s.run.seed = seed.get<std::uint64_t>();

        validate_scene(s, [this](const std::string& field) { return where(field); });
        return s;
    }

private:
    template <class S>
    void read_fields(const json& sec, const std::string& path, S& out, const std::vector<Field<S>>& fields) const {
        for (const auto& f : fields) {
            std::visit(
                [&](auto member) {
                    auto& target = out.*member;
                    using T = std::decay_t<decltype(target)>;
                    if constexpr (std::is_same_v<T, int>)
                        target = integer(sec, path, f.key);
                    else if constexpr (std::is_same_v<T, std::optional<double>>)
                        target = sec.at(f.key).is_null() ? std::nullopt : std::optional(number(sec, path, f.key));
                    else
                        target = number(sec, path, f.key);
                },
                f.member);
        }
    }

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

    // Applies doc[name] (a preset name, or an object with an optional "preset" and overrides).
    void section(const json& doc, const std::string& name, std::optional<assets::Kind> kind,
                 const std::vector<std::string>& keys, json& out, const std::string& prefix = "") {
        if (!doc.contains(name)) return;
        const std::string path = prefix + name;
        json value = doc.at(name);
        if (value.is_string() && kind) value = json{{"preset", value}};
        if (!value.is_object())
            throw InputError(fmt::format("{}: {} must be {}an object, got {}", layer_->origin, path,
                                         kind ? "a preset name or " : "", shown(value)));
        if (value.contains("preset")) {
            if (!kind)
                throw InputError(fmt::format("{}: unknown key '{}.preset' (allowed: {})", layer_->origin, path,
                                             join(keys)));
            const json& p = value.at("preset");
            if (!p.is_string())
                throw InputError(fmt::format("{}: {}.preset must be a preset name, got {}", layer_->origin, path,
                                             shown(p)));
            const std::string preset = p.get<std::string>();
            try {
                for (const auto& [k, v] : assets::preset_values(*kind, preset).items()) {
                    out[k] = v;
                    origins_[path + "." + k] = fmt::format("{} preset '{}'", assets::kind_label(*kind), preset);
                }
            } catch (const InputError& e) {
                throw InputError(fmt::format("{}: {}", label(path + ".preset"), e.what()));
            }
            out["preset"] = preset;
        }
        for (const auto& [k, v] : value.items()) {
            if (k == "preset") continue;
            if (std::find(keys.begin(), keys.end(), k) == keys.end())
                throw InputError(fmt::format("{}: unknown key '{}.{}' (allowed: {}{})", layer_->origin, path, k,
                                             kind ? "preset, " : "", join(keys)));
            out[k] = v;
            origins_[path + "." + k] = label(path + "." + k);
        }
    }

    double number_value(const json& v, const std::string& field) const {
        if (!v.is_number())
            throw InputError(fmt::format("{} = {}{} must be a number", field, shown(v), where(field)));
        const double d = v.get<double>();
        if (!std::isfinite(d))
            throw InputError(fmt::format("{} = {}{} must be a finite number", field, shown(v), where(field)));
        return d;
    }
    double number(const json& sec, const std::string& path, const std::string& key) const {
        return number_value(sec.at(key), path + "." + key);
    }
    int integer(const json& sec, const std::string& path, const std::string& key) const {
        const json& v = sec.at(key);
        const std::string field = path + "." + key;
        if (!v.is_number_integer())
            throw InputError(fmt::format("{} = {}{} must be a whole number", field, shown(v), where(field)));
        const auto i = v.get<std::int64_t>();
        if (i < -1000000000 || i > 1000000000)
            throw InputError(fmt::format("{} = {}{} is far out of range", field, shown(v), where(field)));
        return static_cast<int>(i);
    }

    const SceneLayer* layer_ = nullptr;
    json shell_ = json::object(), ramp_ = json::object(), fidelity_ = json::object();
    json release_ = json::object(), run_ = json::object(), material_ = json::object();
    json fill_ratio_;
    Origins origins_;
};

}  // namespace

SceneLayer read_scene_file(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw InputError(fmt::format("scene file {}: is a directory, expected a JSON file", name));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(fmt::format("scene file {}: cannot be read", name));
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
                                                    field.empty() ? "" : " after key '" + field + "'", e.what())));
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

std::string to_string(ReleasePose pose) { return pose == ReleasePose::vertex ? "vertex" : "face"; }

std::string to_string(Model model) {
    switch (model) {
        case Model::grains: return "grains";
        case Model::segments: return "segments";
        case Model::rigid: return "rigid";
    }
    return "unknown";
}

nlohmann::ordered_json scene_to_json(const Scene& s) {
    auto section = [](const std::string& preset) {
        json sec = json::object();
        if (!preset.empty()) sec["preset"] = preset;
        return sec;
    };
    json j;
    json shell = section(s.shell.preset);
    write_fields(shell, s.shell, kShellFields);
    j["shell"] = shell;
    json material = section(s.fill.material.preset);
    write_fields(material, s.fill.material, kMaterialFields);
    j["fill"] = json{{"ratio", s.fill.ratio}, {"material", material}};
    json ramp = section(s.ramp.preset);
    write_fields(ramp, s.ramp, kRampFields);
    j["ramp"] = ramp;
    json release = json{{"pose", to_string(s.release.pose)}};
    write_fields(release, s.release, kReleaseFields);
    j["release"] = release;
    json fidelity = section(s.fidelity.preset);
    write_fields(fidelity, s.fidelity, kFidelityFields);
    j["fidelity"] = fidelity;
    json run = json{{"model", to_string(s.run.model)}, {"seed", s.run.seed}};
    write_fields(run, s.run, kRunFields);
    j["run"] = run;
    return j;
}

}  // namespace polyroll
