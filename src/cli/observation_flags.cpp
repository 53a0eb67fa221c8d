// Scene flags on top of every observation: see observation_flags.h.
#include "cli/observation_flags.h"

#include <algorithm>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "cli/scene_options.h"
#include "sim/errors.h"
#include "sim/scene/scene_fields.h"
#include "sweep/grid_values.h"

namespace polyroll::cli {

using json = nlohmann::ordered_json;

void add_observation_scene_flags(flags::Command& sub, const std::shared_ptr<ObservationSceneFlags>& flags) {
    // No --param alias: beside calibrate's --params it read as the same flag, and its errors named
    // --set; one name, the one every error uses.
    sub.add_option("--set", flags->sets, "any scene field on top of every observation: FIELD=VALUE, e.g. "
                                         "--set fill.material.wall_friction=0.05 (repeatable)")
        .group("Scene");
    // Every scene flag but the seed (--seeds gives those), from the field table.
    for (const SceneField& f : scene_fields()) {
        if (f.flag.empty() || f.type == FieldType::seed) continue;
        const std::string path(f.path);
        flags::Flag o = sub.add_option_function(
                               std::string(f.flag),
                               [flags, path](const std::string& v) { flags->scene_text[path].first = v; },
                               field_help(f) + " (on top of every observation)")
                            .group("Scene");
        flags->scene_text[path] = {"", o};
    }
}

std::vector<std::pair<std::string, json>> observation_overrides(const ObservationSceneFlags& a) {
    std::vector<std::pair<std::string, json>> out;
    for (const SceneField& f : scene_fields()) {
        const auto it = a.scene_text.find(std::string(f.path));
        if (it == a.scene_text.end() || it->second.second.count() == 0) continue;
        const std::string flag = it->second.second.name();
        const std::vector<json> v = sweep::parse_grid_values(flag, it->second.first);
        if (v.size() != 1) throw InputError(fmt::format("{} {}: one value (allowed: a single value, applied to every observation)", flag, it->second.first));
        out.emplace_back(std::string(f.path), v.front());
    }
    for (const std::string& s : a.sets) {
        std::pair<std::string, json> set = parse_set_flag(s);
        if (set.first == "run.seed") throw InputError("--set run.seed: not allowed (--seeds N gives the seeds)");
        out.erase(std::remove_if(out.begin(), out.end(), [&](const auto& o) { return o.first == set.first; }), out.end());
        out.push_back(std::move(set));
    }
    return out;
}

std::vector<std::string> observation_flags_args(const ObservationSceneFlags& a) {
    std::vector<std::string> out;
    for (const SceneField& f : scene_fields()) {
        const auto it = a.scene_text.find(std::string(f.path));
        if (it == a.scene_text.end() || it->second.second.count() == 0) continue;
        out.push_back(it->second.second.name());
        out.push_back(it->second.first);
    }
    for (const std::string& s : a.sets) {
        out.push_back("--set");
        out.push_back(s);
    }
    return out;
}

std::string observation_flags_text(const ObservationSceneFlags& a) {
    std::string out;
    for (const SceneField& f : scene_fields()) {
        const auto it = a.scene_text.find(std::string(f.path));
        if (it == a.scene_text.end() || it->second.second.count() == 0) continue;
        out += fmt::format(" {} {}", it->second.second.name(), it->second.first);
    }
    for (const std::string& s : a.sets) out += " --set " + s;
    return out;
}

}  // namespace polyroll::cli
