// The command-line flags that describe a scene (--sides, --fill, ...): one per field with a flag in
// sim/scene/scene_fields.cpp, shared by every command that runs one. They become the last layer over
// assets/defaults.json and any --scene file.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "flags/command_flags.h"

#include "sim/scene/scene.h"
#include "sim/scene/scene_fields.h"
#include "sim/scene/scene_json.h"
#include "sim/scene/window_presets.h"

namespace polyroll::cli {

// The field's value in the default scene (assets/defaults.json) as help shows it: "(default: 20)";
// "" when it has none or the assets cannot be read while help is set up (the command reports that).
std::string default_note(const SceneField& f);

// One --set FIELD=VALUE, as every command that takes it reads it: the field checked against the
// scene's paths, one value parsed as a scene file holds it (null unsets an optional field).
// InputError naming the text otherwise, a list included (sweep reads its lists itself).
std::pair<std::string, nlohmann::ordered_json> parse_set_flag(const std::string& text);

class SceneOptions {
public:
    // Registers one flag per field that has one, but the fields in `without` (paths, e.g. "run.model":
    // a command that sets that field itself does not list a flag it would ignore), and --set for
    // any other field.
    void add_to(flags::Command& app, const std::vector<std::string>& without = {});
    // --preset NAME and --lane K: a window preset's lane (assets/sandbox-presets.json) in place of
    // --scene, the flags over it. For the commands that run one scene (run) or draw a preset's lanes
    // (render).
    void add_preset_to(flags::Command& app);
    // Resolves and validates the scene; throws InputError (for a --preset of several lanes without
    // --lane too).
    Scene resolve() const;
    // Every lane: a --preset's lanes (just the --lane if given), each under the flags; otherwise the
    // one scene resolve() gives.
    std::vector<Scene> resolve_lanes() const;
    // The --preset named ("" without one).
    const std::string& preset() const { return preset_; }

private:
    struct Flag {
        flags::Flag option;
        std::string field;                           // e.g. "shell.sides"
        std::function<nlohmann::ordered_json()> value;  // the parsed value, as JSON
    };
    template <class T>
    void add_flag(flags::Command& app, const SceneField& f, const std::string& help);

    // --set FIELD=VALUE: any field of a scene file, as sweep, validate and calibrate take it.
    std::vector<std::pair<std::string, nlohmann::ordered_json>> parsed_sets() const;

    // The flags' and --set's layer, over the scene file or the preset's lane.
    SceneLayer cli_layer() const;
    // The preset's lane `k` (1-based) under the flags.
    Scene resolve_lane(const WindowPreset& preset, int k) const;

    std::string scene_file_;
    flags::Flag scene_option_;
    std::string preset_;
    int lane_ = 0;
    flags::Flag preset_option_, lane_option_;
    std::vector<Flag> flags_;
    std::vector<std::string> sets_;
    std::vector<std::string> without_;  // fields the command sets itself: no flag, and refused by --set
};

}  // namespace polyroll::cli
