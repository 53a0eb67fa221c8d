// Materials and presets are data: a fourth material and a preset for it, written into a scratch asset
// folder (POLYROLL_ASSETS), show in the CLI, in the frames and on the sandbox panel with no code
// change; and the bundled ones look exactly as they always have.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/controls.h"
#include "app/sandbox_presets.h"
#include "render/colour.h"
#include "render/font.h"
#include "render/frame_builder.h"
#include "render/frame_layout.h"
#include "render/overlay.h"
#include "render/snapshot.h"
#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/scene/scene_json.h"
#include "known_snapshot.h"
#include "test_helpers.h"

using namespace polyroll;
using json = nlohmann::ordered_json;
namespace fs = std::filesystem;

namespace {

json bundled(std::string_view name) {
    for (const auto& f : assets::embedded_files())
        if (f.name == name) return json::parse(f.text);
    return json();
}

// A scratch asset folder: materials.json with red lentils added, sandbox-presets.json with a
// hexagon of them in the hexagon row. Each test case names its own folder: ctest runs them at once.
fs::path lentil_assets(const std::string& name) {
    const fs::path dir = test::scratch_dir("asset-folder-" + name, true);
    json materials = bundled("materials.json");
    materials["presets"]["lentils"] = json::parse(R"({
        "description": "red lentils: small flat discs",
        "look": {"label": "red lentils", "rgb": [200, 90, 40],
                 "sources": {"label": "test", "rgb": "test"}},
        "values": {"diameter_m": 0.0045, "diameter_spread": 0.08, "bulk_density_kg_m3": 850,
                   "friction": 0.45, "wall_friction": 0.35, "restitution": 0.2},
        "sources": {"diameter_m": "test", "diameter_spread": "test", "bulk_density_kg_m3": "test",
                    "friction": "test", "wall_friction": "test", "restitution": "test"}})");
    std::ofstream(dir / "materials.json") << materials.dump(2);
    json presets = bundled("sandbox-presets.json");
    presets["presets"]["hexagon-lentils"] = json::parse(R"({
        "description": "the hexagon (small) half full of red lentils",
        "row": "hexagon",
        "lanes": [{"shell": "hexagon-small", "fill": {"ratio": 0.5, "material": "lentils"}}],
        "sources": {"fill.material": "test"}})");
    std::ofstream(dir / "sandbox-presets.json") << presets.dump(2);
    return dir;
}

// Reads the assets from `dir` while alive, then the bundled ones again.
struct UsingAssets {
    explicit UsingAssets(const fs::path& dir) { assets::use_directory(dir); }
    ~UsingAssets() { assets::use_directory({}); }
    UsingAssets(const UsingAssets&) = delete;
    UsingAssets& operator=(const UsingAssets&) = delete;
};

test::CommandResult polyroll_with(const fs::path& dir, const std::string& args) {
    return test::run_command(std::string(assets::kDirectoryVariable) + "=" + dir.string() + " " + POLYROLL_EXE + " " +
                             args);
}

const app::PresetRow* row_named(const app::PresetPanel& panel, const std::string& label) {
    for (const auto& r : panel.rows)
        if (r.label == label) return &r;
    return nullptr;
}

}  // namespace

TEST_CASE("the bundled materials look as they always have", "[assets][render]") {
    CHECK(render::material_colour("bb") == render::rgb8(236, 170, 30));
    CHECK(render::material_colour("peas") == render::rgb8(96, 160, 50));
    CHECK(render::material_colour("rice") == render::rgb8(250, 246, 228));
    CHECK(render::material_colour("") == render::rgb8(170, 120, 200));
    CHECK(render::material_colour("gravel") == render::rgb8(170, 120, 200));
    CHECK(render::material_label("bb") == "BBs");
    CHECK(render::material_label("rice") == "rice");
    CHECK(render::material_label("peas") == "peas");
    CHECK(render::material_label("") == "custom grains");
    CHECK(render::material_label("gravel") == "gravel");
    // Every look says where it comes from.
    for (const std::string& name : assets::preset_names(assets::Kind::material)) {
        const json& look = assets::preset_entry(assets::Kind::material, name).at("look");
        INFO(name);
        for (const char* key : {"label", "rgb"}) CHECK(look.at("sources").contains(key));
    }
}

TEST_CASE("the panel's preset rows: one per polygon, a button per material, then the rest", "[assets][app]") {
    const app::PresetPanel panel = app::preset_panel();
    std::vector<std::string> rows;
    for (const auto& r : panel.rows) rows.push_back(r.label);
    CHECK(rows == std::vector<std::string>{"hexagon", "octagon", "decagon", "octadecagon", "hexagon-large"});
    for (const auto& r : panel.rows) {
        std::vector<std::string> labels, presets;
        for (const auto& b : r.buttons) {
            labels.push_back(b.label);
            presets.push_back(b.preset);
            CHECK(b.tooltip == "Preset '" + b.preset + "': " + app::sandbox_preset(b.preset).description);
        }
        CHECK(labels == std::vector<std::string>{"BBs", "rice", "peas"});
        CHECK(presets == std::vector<std::string>{r.label + "-bb", r.label + "-rice", r.label + "-peas"});
    }
    std::vector<std::string> others;
    for (const auto& b : panel.others) others.push_back(b.label);
    CHECK(others == std::vector<std::string>{"default", "race"});
}

TEST_CASE("a fourth material in a scratch asset folder shows in the CLI", "[assets][cli]") {
    const fs::path dir = lentil_assets("cli");
    const test::CommandResult presets = polyroll_with(dir, "presets");
    CHECK(presets.exit_code == 0);
    CHECK(presets.out.find("lentils") != std::string::npos);
    CHECK(presets.out.find("red lentils: small flat discs") != std::string::npos);
    // The flags' help lists the presets from the files.
    const test::CommandResult help = polyroll_with(dir, "run --help");
    CHECK(help.out.find("bb, rice, peas, lentils") != std::string::npos);
    const test::CommandResult bad = polyroll_with(dir, "run --material gravel --out " + (dir / "bad").string());
    CHECK(bad.exit_code == 2);
    CHECK(bad.out.find("bb, rice, peas, lentils") != std::string::npos);
    // A run with it.
    const fs::path out = dir / "run";
    const test::CommandResult run =
        polyroll_with(dir, "run --material lentils --fill 0.1 --fidelity draft --time-limit 0.2 --out " + out.string());
    INFO(run.out);
    REQUIRE(run.exit_code == 0);
    const json summary = json::parse(test::read_file(out / "summary.json"));
    CHECK(summary.at("scene").at("fill").at("material").at("preset") == "lentils");
    CHECK(summary.at("scene").at("fill").at("material").at("diameter_m") == 0.0045);
    // Without the folder, the bundled files know no lentils.
    const test::CommandResult plain = test::run_command(std::string(POLYROLL_EXE) + " presets");
    CHECK(plain.out.find("lentils") == std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("a replacement asset file that is not JSON is one line naming it, exit 2", "[assets][cli][bad-input]") {
    const fs::path dir = test::scratch_dir("asset-folder-bad", true);
    std::ofstream(dir / "materials.json") << "{\"presets\": ";
    const test::CommandResult r = polyroll_with(dir, "presets");
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("materials.json") != std::string::npos);
    CHECK(r.out.find("not valid JSON") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("a replacement materials.json without a field is refused naming the field and the preset", "[assets][cli][bad-input]") {
    // As a materials.json written before packing_fraction existed would be.
    const fs::path dir = test::scratch_dir("asset-folder-old-materials", true);
    json materials = bundled("materials.json");
    for (auto& [name, preset] : materials.at("presets").items()) preset.at("values").erase("packing_fraction");
    std::ofstream(dir / "materials.json") << materials.dump(2);
    const fs::path out = dir / "run";
    const test::CommandResult r = polyroll_with(dir, "run --out " + out.string());
    INFO(r.out);
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("fill.material.packing_fraction is not set: preset 'bb' does not give it") != std::string::npos);
    CHECK(!fs::exists(out / "summary.json"));
    fs::remove_all(dir);
}

TEST_CASE("a fourth material in a scratch asset folder shows in the frames", "[assets][render]") {
    const fs::path dir = lentil_assets("frames");
    const UsingAssets using_them(dir);
    CHECK(render::material_label("lentils") == "red lentils");
    CHECK(render::material_colour("lentils") == render::rgb8(200, 90, 40));
    // The draw list: every grain in the lentils' colour.
    render::Snapshot s = test::known_snapshot();
    s.material = "lentils";
    render::FrameOptions o;
    o.width_px = 640;
    o.height_px = 360;
    const render::FontAtlas font(render::find_font_dir(), render::frame_fonts(o));
    const render::DrawList dl = render::build_frame(s, o, font);
    REQUIRE(!dl.layers.empty());
    int grains = 0;
    for (const render::Shape& shape : dl.layers.front().shapes) {
        if (shape.tag != render::Tag::grain) continue;
        ++grains;
        CHECK(shape.fill == render::rgb8(200, 90, 40));
    }
    CHECK(grains == 3);  // the snapshot's three
    fs::remove_all(dir);
}

TEST_CASE("a fourth material in a scratch asset folder shows on the sandbox panel", "[assets][app]") {
    const fs::path dir = lentil_assets("panel");
    const UsingAssets using_them(dir);
    // The material combo's choices.
    const std::vector<std::string> materials = assets::preset_names(assets::Kind::material);
    CHECK(std::find(materials.begin(), materials.end(), "lentils") != materials.end());
    // The preset grid: a fourth button in the hexagon row, labelled with the material's label.
    const app::PresetPanel panel = app::preset_panel();
    const app::PresetRow* hexagon = row_named(panel, "hexagon");
    REQUIRE(hexagon != nullptr);
    REQUIRE(hexagon->buttons.size() == 4);
    CHECK(hexagon->buttons.back().preset == "hexagon-lentils");
    CHECK(hexagon->buttons.back().label == "red lentils");
    // Choosing it sets the lane's friction and restitution, and the lane's scene resolves.
    app::LaneControls lane = app::lane_controls_from(resolve_scene({}));
    const app::SharedControls shared = app::shared_controls_from(resolve_scene({}));
    app::set_material(lane, "lentils");
    CHECK(lane.values.fill.material.friction == 0.45);
    CHECK(lane.values.fill.material.restitution == 0.2);
    const Scene scene = app::lane_scene(json::object(), lane, shared);
    CHECK(scene.fill.material.diameter_m == 0.0045);
    const std::vector<Scene> lanes = app::resolve_preset(app::sandbox_preset("hexagon-lentils"));
    CHECK(lanes.front().fill.material.preset == "lentils");
    fs::remove_all(dir);
}
