// polyroll presets: the bundled polygons, materials, ramps and fidelity levels, from assets/ (or the
// folder POLYROLL_ASSETS names).
#include <string>
#include <string_view>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "sim/assets.h"
#include "sim/geometry/shell_properties.h"
#include "sim/scene/window_presets.h"

namespace polyroll::cli {

namespace {

// What null means for the optional preset values.
std::string value_text(std::string_view key, const nlohmann::ordered_json& v) {
    if (v.is_null()) {
        if (key == "lid_mass_fraction") return "null (split by volume)";
        if (key == "grains_per_disc") return "null (a column of grains through the box)";
        return "null";
    }
    if (v.is_number_float()) return fmt::format("{:g}", v.get<double>());
    return v.dump();
}

// A race lane in a line: "the small hexagon half full of BBs, 18 deg on the air-track ramp".
std::string lane_text(const Scene& s) {
    const std::string fill = s.fill.ratio > 0.0 ? fmt::format("r = {:g} {}", s.fill.ratio, s.fill.material.preset)
                                                : std::string("empty");
    return fmt::format("{}, {}, {:g} deg on {}", s.shell.preset.empty() ? fmt::format("n = {}", s.shell.sides)
                                                                        : s.shell.preset,
                       fill, s.ramp.angle_deg, s.ramp.preset.empty() ? "a custom ramp" : s.ramp.preset);
}

int list(bool as_json) {
    using assets::Kind;
    const std::vector<Kind>& kinds = assets::all_kinds();
    if (as_json) {
        nlohmann::ordered_json out;
        for (Kind k : kinds) out[std::string(assets::kind_label(k))] = assets::file(assets::kind_file(k)).at("presets");
        out["window"] = assets::file("sandbox-presets.json").at("presets");
        out["observations"] = assets::file("experiment.json").at("observations");
        fmt::print("{}\n", out.dump(2));
        return kExitOk;
    }
    if (const auto dir = assets::directory(); !dir.empty())
        fmt::print("{}={}: its asset files replace the bundled ones\n\n", assets::kDirectoryVariable, dir.string());
    for (Kind k : kinds) {
        // Plural by hand: "fidelitys" is not a word.
        const std::string_view label = assets::kind_label(k);
        fmt::print("{} (assets/{}):\n", label == "fidelity" ? std::string("fidelity levels") : std::string(label) + "s",
                   assets::kind_file(k));
        for (const std::string& name : assets::preset_names(k)) {
            const auto& entry = assets::preset_entry(k, name);
            fmt::print("  {:<18} {}\n", name, entry.at("description").get<std::string>());
            std::string values;
            for (const auto& [key, v] : entry.at("values").items())
                values += fmt::format("{}{} = {}", values.empty() ? "" : ", ", key, value_text(key, v));
            fmt::print("  {:<18} {}\n", "", values);
        }
        fmt::print("\n");
    }
    // The window's whole scenes, each with its lanes, and which surface takes them; then the
    // observations validate and calibrate score (--only ID).
    fmt::print("window presets (assets/sandbox-presets.json), whole scenes of one lane or a race of several:\n");
    for (const std::string& name : window_preset_names()) {
        const WindowPreset preset = window_preset(name);
        const std::vector<Scene> lanes = resolve_window_preset(preset);
        fmt::print("  {:<24} {}\n", lanes.size() > 1 ? fmt::format("{} ({} lanes)", name, lanes.size()) : name,
                   preset.description);
        if (lanes.size() > 1)
            for (size_t k = 0; k < lanes.size(); ++k)
                fmt::print("  {:<24}   lane {}: {}\n", "", k + 1, lane_text(lanes[k]));
    }
    fmt::print("  Which surface takes which:\n"
               "    the window     polyroll-sandbox --preset NAME          every preset, a race's lanes side by side\n"
               "    the page       index.html?preset=NAME                  every preset, as the window\n"
               "    render         polyroll render --preset NAME --out DIR every preset, a race's lanes side by side\n"
               "                   (--lane K: one lane)\n"
               "    run            polyroll run --preset NAME [--lane K]   one lane: a race needs --lane\n"
               "    Python         polyroll.run(preset=NAME, lane=K)       one lane: a race needs lane=; also\n"
               "                   polyroll.Simulation and polyroll.scene; polyroll.window_presets() lists them\n");
    fmt::print("\nobservations (assets/experiment.json; polyroll validate --only ID):\n");
    for (const auto& ob : assets::file("experiment.json").at("observations"))
        fmt::print("  {:<36} {}\n", ob.at("id").get<std::string>(), ob.value("source", std::string()));
    fmt::print("\nEach value's source (a measurement of the experiment, or a stated choice and why) is in the\n"
               "file named above, under \"sources\"; 'polyroll presets --json' prints them all.\n");
    return kExitOk;
}

}  // namespace

Action add_presets_command(Command& app) {
    auto as_json = std::make_shared<bool>(false);
    Command sub = app.add_subcommand("presets", "list the bundled polygons, materials, ramps, fidelity levels, the "
                                                "window's presets and the experiment's observations");
    sub.footer(fmt::format("The presets are the files of assets/, compiled in. {}=DIR reads any of them from DIR "
                           "instead (e.g. DIR/materials.json with a material of your own), for every command and "
                           "polyroll-sandbox.\n"
                           "Examples:\n"
                           "  polyroll presets\n"
                           "  polyroll presets --json > presets.json\n"
                           "  polyroll render --preset race --out frames/race   # a window preset, headless\n"
                           "  {}=my-assets polyroll presets       # my-assets/materials.json and the rest",
                           assets::kDirectoryVariable, assets::kDirectoryVariable));
    sub.add_flag("--json", *as_json, "print them, with their sources, as JSON");
    return [as_json] { return list(*as_json); };
}

}  // namespace polyroll::cli
