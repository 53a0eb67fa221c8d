// Scene JSON: layering presets and overrides, type checks, and the resolved form. See scene_json.h.
#include "sim/scene_json.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/scene_validate.h"

namespace polyroll {
namespace {

using json = nlohmann::ordered_json;

// The keys each section takes besides "preset", in output order.
const std::vector<std::string> kShellKeys = {"sides", "inner_circumradius_m", "wall_thickness_m", "depth_m",
                                             "lid_thickness_m", "mass_kg", "lid_mass_fraction"};
const std::vector<std::string> kMaterialKeys = {"diameter_m", "diameter_spread", "bulk_density_kg_m3",
                                                "friction", "wall_friction", "restitution"};
const std::vector<std::string> kRampKeys = {"length_m", "friction", "restitution", "angle_deg"};
const std::vector<std::string> kReleaseKeys = {"pose", "tilt_deg"};
const std::vector<std::string> kFidelityKeys = {"step_hz", "substeps", "velocity_iterations",
                                                "position_iterations"};
const std::vector<std::string> kRunKeys = {"model", "seed", "time_limit_s", "sample_hz", "gravity_m_s2",
                                           "settle_time_s", "rest_speed_m_s", "rest_time_s"};
const std::vector<std::string> kSections = {"shell", "fill", "ramp", "release", "fidelity", "run"};

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
        SceneLayer defaults{assets::default_scene_json(), "assets/defaults.json", {}};
        apply(defaults);
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
                                             layer.origin, fill.dump()));
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
        s.shell.sides = integer(shell_, "shell", "sides");
        s.shell.inner_circumradius_m = number(shell_, "shell", "inner_circumradius_m");
        s.shell.wall_thickness_m = number(shell_, "shell", "wall_thickness_m");
        s.shell.depth_m = number(shell_, "shell", "depth_m");
        s.shell.lid_thickness_m = number(shell_, "shell", "lid_thickness_m");
        s.shell.mass_kg = number(shell_, "shell", "mass_kg");
        if (!shell_.at("lid_mass_fraction").is_null())
            s.shell.lid_mass_fraction = number(shell_, "shell", "lid_mass_fraction");

        s.fill.ratio = number_value(fill_ratio_, "fill.ratio");
        s.fill.material.preset = material_.value("preset", "");
        s.fill.material.diameter_m = number(material_, "fill.material", "diameter_m");
        s.fill.material.diameter_spread = number(material_, "fill.material", "diameter_spread");
        s.fill.material.bulk_density_kg_m3 = number(material_, "fill.material", "bulk_density_kg_m3");
        s.fill.material.friction = number(material_, "fill.material", "friction");
        s.fill.material.wall_friction = number(material_, "fill.material", "wall_friction");
        s.fill.material.restitution = number(material_, "fill.material", "restitution");

        s.ramp.preset = ramp_.value("preset", "");
        s.ramp.length_m = number(ramp_, "ramp", "length_m");
        s.ramp.friction = number(ramp_, "ramp", "friction");
        s.ramp.restitution = number(ramp_, "ramp", "restitution");
        s.ramp.angle_deg = number(ramp_, "ramp", "angle_deg");

        const json& pose = release_.at("pose");
        if (pose == "vertex") s.release.pose = ReleasePose::vertex;
        else if (pose == "face") s.release.pose = ReleasePose::face;
        else throw InputError(fmt::format("release.pose = {}{} is not allowed (allowed: vertex, face)",
                                          pose.dump(), where("release.pose")));
        s.release.tilt_deg = number(release_, "release", "tilt_deg");

        s.fidelity.preset = fidelity_.value("preset", "");
        s.fidelity.step_hz = number(fidelity_, "fidelity", "step_hz");
        s.fidelity.substeps = integer(fidelity_, "fidelity", "substeps");
        s.fidelity.velocity_iterations = integer(fidelity_, "fidelity", "velocity_iterations");
        s.fidelity.position_iterations = integer(fidelity_, "fidelity", "position_iterations");

        const json& model = run_.at("model");
        if (model == "grains") s.run.model = Model::grains;
        else if (model == "segments") s.run.model = Model::segments;
        else if (model == "rigid") s.run.model = Model::rigid;
        else throw InputError(fmt::format("run.model = {}{} is not allowed (allowed: grains, segments, rigid)",
                                          model.dump(), where("run.model")));

        const json& seed = run_.at("seed");
        if (!seed.is_number_unsigned())
            throw InputError(fmt::format("run.seed = {}{} must be a whole number from 0 to 2^64-1", seed.dump(),
                                         where("run.seed")));
        s.run.seed = seed.get<std::uint64_t>();
        s.run.time_limit_s = number(run_, "run", "time_limit_s");
        s.run.sample_hz = number(run_, "run", "sample_hz");
        s.run.gravity_m_s2 = number(run_, "run", "gravity_m_s2");
        s.run.settle_time_s = number(run_, "run", "settle_time_s");
        s.run.rest_speed_m_s = number(run_, "run", "rest_speed_m_s");
        s.run.rest_time_s = number(run_, "run", "rest_time_s");

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

    // Applies doc[name] (a preset name, or an object with an optional "preset" and overrides).
    void section(const json& doc, const std::string& name, std::optional<assets::Kind> kind,
                 const std::vector<std::string>& keys, json& out, const std::string& prefix = "") {
        if (!doc.contains(name)) return;
        const std::string path = prefix + name;
        json value = doc.at(name);
        if (value.is_string() && kind) value = json{{"preset", value}};
        if (!value.is_object())
            throw InputError(fmt::format("{}: {} must be {}an object, got {}", layer_->origin, path,
                                         kind ? "a preset name or " : "", value.dump()));
        if (value.contains("preset")) {
            if (!kind)
                throw InputError(fmt::format("{}: unknown key '{}.preset' (allowed: {})", layer_->origin, path,
                                             join(keys)));
            const json& p = value.at("preset");
            if (!p.is_string())
                throw InputError(fmt::format("{}: {}.preset must be a preset name, got {}", layer_->origin, path,
                                             p.dump()));
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
            throw InputError(fmt::format("{} = {}{} must be a number", field, v.dump(), where(field)));
        const double d = v.get<double>();
        if (!std::isfinite(d))
            throw InputError(fmt::format("{} = {}{} must be a finite number", field, v.dump(), where(field)));
        return d;
    }
    double number(const json& sec, const std::string& path, const std::string& key) const {
        return number_value(sec.at(key), path + "." + key);
    }
    int integer(const json& sec, const std::string& path, const std::string& key) const {
        const json& v = sec.at(key);
        const std::string field = path + "." + key;
        if (!v.is_number_integer())
            throw InputError(fmt::format("{} = {}{} must be a whole number", field, v.dump(), where(field)));
        const auto i = v.get<std::int64_t>();
        if (i < -1000000000 || i > 1000000000)
            throw InputError(fmt::format("{} = {}{} is far out of range", field, v.dump(), where(field)));
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
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw InputError(fmt::format("scene file {}: is a directory, expected a JSON file", path.string()));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(fmt::format("scene file {}: cannot be read", path.string()));
    std::stringstream buffer;
    buffer << in.rdbuf();
    SceneLayer layer;
    layer.origin = path.string();
    try {
        layer.doc = nlohmann::ordered_json::parse(buffer.str());
    } catch (const nlohmann::json::parse_error& e) {
        // nlohmann's message names the byte offset and the token; keep it on one line.
        std::string what = e.what();
        std::replace(what.begin(), what.end(), '\n', ' ');
        throw InputError(fmt::format("scene file {}: not valid JSON: {}", path.string(), what));
    }
    if (!layer.doc.is_object())
        throw InputError(fmt::format("scene file {}: a scene must be a JSON object", path.string()));
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
    json j;
    auto preset = [](json& sec, const std::string& name) {
        if (!name.empty()) sec["preset"] = name;
    };
    json shell = json::object();
    preset(shell, s.shell.preset);
    shell["sides"] = s.shell.sides;
    shell["inner_circumradius_m"] = s.shell.inner_circumradius_m;
    shell["wall_thickness_m"] = s.shell.wall_thickness_m;
    shell["depth_m"] = s.shell.depth_m;
    shell["lid_thickness_m"] = s.shell.lid_thickness_m;
    shell["mass_kg"] = s.shell.mass_kg;
    shell["lid_mass_fraction"] = s.shell.lid_mass_fraction ? json(*s.shell.lid_mass_fraction) : json(nullptr);
    j["shell"] = shell;

    json material = json::object();
    preset(material, s.fill.material.preset);
    material["diameter_m"] = s.fill.material.diameter_m;
    material["diameter_spread"] = s.fill.material.diameter_spread;
    material["bulk_density_kg_m3"] = s.fill.material.bulk_density_kg_m3;
    material["friction"] = s.fill.material.friction;
    material["wall_friction"] = s.fill.material.wall_friction;
    material["restitution"] = s.fill.material.restitution;
    j["fill"] = json{{"ratio", s.fill.ratio}, {"material", material}};

    json ramp = json::object();
    preset(ramp, s.ramp.preset);
    ramp["length_m"] = s.ramp.length_m;
    ramp["friction"] = s.ramp.friction;
    ramp["restitution"] = s.ramp.restitution;
    ramp["angle_deg"] = s.ramp.angle_deg;
    j["ramp"] = ramp;

    j["release"] = json{{"pose", to_string(s.release.pose)}, {"tilt_deg", s.release.tilt_deg}};

    json fidelity = json::object();
    preset(fidelity, s.fidelity.preset);
    fidelity["step_hz"] = s.fidelity.step_hz;
    fidelity["substeps"] = s.fidelity.substeps;
    fidelity["velocity_iterations"] = s.fidelity.velocity_iterations;
    fidelity["position_iterations"] = s.fidelity.position_iterations;
    j["fidelity"] = fidelity;

    j["run"] = json{{"model", to_string(s.run.model)},
                    {"seed", s.run.seed},
                    {"time_limit_s", s.run.time_limit_s},
                    {"sample_hz", s.run.sample_hz},
                    {"gravity_m_s2", s.run.gravity_m_s2},
                    {"settle_time_s", s.run.settle_time_s},
                    {"rest_speed_m_s", s.run.rest_speed_m_s},
                    {"rest_time_s", s.run.rest_time_s}};
    return j;
}

}  // namespace polyroll
