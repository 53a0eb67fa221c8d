// The scene field table (sim/scene/scene_fields.h): it names every field the scene files hold, in their
// order; its limits give the messages validation has always given; its flags are unique.
#include <catch2/catch.hpp>

#include <set>

#include <nlohmann/json.hpp>

#include "sim/errors.h"
#include "sim/model_registry.h"
#include "sim/scene/scene_fields.h"
#include "sim/scene/scene_json.h"
#include "sim/scene/scene_names.h"
#include "test_helpers.h"

using namespace polyroll;
using json = nlohmann::ordered_json;

namespace {

void leaf_paths(const json& j, const std::string& prefix, std::vector<std::string>& out) {
    for (const auto& [k, v] : j.items()) {
        const std::string path = prefix.empty() ? k : prefix + "." + k;
        if (v.is_object()) leaf_paths(v, path, out);
        else out.push_back(path);
    }
}

// The scene file's format as users' files hold it, written out by hand: the fields in their order.
// Neither the table nor the writer can change it unnoticed; a new field is added here on purpose.
const std::vector<std::string> kSceneFileFields = {
    "shell.preset", "shell.sides", "shell.inner_circumradius_m", "shell.wall_thickness_m", "shell.depth_m",
    "shell.lid_thickness_m", "shell.mass_kg", "shell.lid_mass_fraction", "shell.vertex_radius_m",
    "fill.ratio", "fill.material.preset", "fill.material.diameter_m", "fill.material.diameter_spread",
    "fill.material.bulk_density_kg_m3", "fill.material.friction", "fill.material.wall_friction",
    "fill.material.lid_friction", "fill.material.restitution", "fill.material.packing_fraction",
    "fill.material.grains_per_disc",
    "ramp.preset", "ramp.length_m", "ramp.friction", "ramp.restitution", "ramp.angle_deg",
    "ramp.curvature_deg_per_m",
    "release.pose", "release.tilt_deg", "release.pile_tilt_deg",
    "fidelity.preset", "fidelity.step_hz", "fidelity.substeps", "fidelity.velocity_iterations",
    "fidelity.position_iterations",
    "fidelity.frame", "fidelity.contacts",
    "run.model", "run.seed", "run.time_limit_s", "run.sample_hz", "run.gravity_m_s2", "run.settle_time_s",
    "run.rest_speed_m_s", "run.rest_time_s", "run.end_at_impact",
    "dem3d.contact_time_s", "dem3d.time_step_share", "dem3d.channel_width_m",
    "closure.preset", "closure.disc_friction_factor", "closure.wall_friction_factor", "closure.restitution_factor",
    "closure.disc_size_spread", "closure.bulk_factor",
};

}  // namespace

TEST_CASE("the field table holds every field of a scene file, in its order", "[scene][fields]") {
    // The default scene names every preset, so the writer leaves none of its fields out.
    std::vector<std::string> written;
    leaf_paths(scene_to_json(resolve_scene({})), "", written);
    CHECK(written == kSceneFileFields);
    std::vector<std::string> table;
    for (const SceneField& f : scene_fields()) table.emplace_back(f.path);
    CHECK(table == kSceneFileFields);
    // Each field round-trips through its accessor.
    const Scene s = resolve_scene({});
    for (const SceneField& f : scene_fields()) {
        Scene copy;
        f.access.set(copy, f.access.get(s));
        CHECK(f.access.get(copy) == f.access.get(s));
    }
}

TEST_CASE("each field's row reads and writes its own member and no other", "[scene][fields]") {
    // A row whose member chain names the wrong member (two rows on one member, or a row writing one
    // member and reading another) changes some other field or does not hold the value set.
    const Scene base = resolve_scene({});
    for (const SceneField& f : scene_fields()) {
        FieldValue changed = f.access.get(base);
        if (auto* d = std::get_if<double>(&changed)) *d += 0.125;
        else if (auto* i = std::get_if<int>(&changed)) *i += 1;
        else if (auto* o = std::get_if<std::optional<double>>(&changed)) *o = o->value_or(0.0) + 0.125;
        else if (auto* seed = std::get_if<std::uint64_t>(&changed)) *seed += 1;
        else if (auto* text = std::get_if<std::string>(&changed)) *text += "-changed";
        else continue;  // the enumerations: two values each, their rows' names are checked elsewhere
        Scene s = base;
        f.access.set(s, changed);
        INFO(f.path);
        CHECK(f.access.get(s) == changed);
        for (const SceneField& g : scene_fields())
            if (g.path != f.path) CHECK(g.access.get(s) == g.access.get(base));
    }
}

TEST_CASE("flags are unique and the sweep's axes are numbered 1, 2, ...", "[scene][fields]") {
    std::set<std::string_view> flags;
    std::vector<int> axes;
    for (const SceneField& f : scene_fields()) {
        if (!f.flag.empty()) CHECK(flags.insert(f.flag).second);
        if (f.sweep_axis > 0) axes.push_back(f.sweep_axis);
        CHECK(!f.help.empty());
        if (f.type == FieldType::preset) CHECK(f.kind.has_value());
        if (f.type == FieldType::choice) CHECK((f.choice_names && f.choice_named));
    }
    std::sort(axes.begin(), axes.end());
    for (size_t i = 0; i < axes.size(); ++i) CHECK(axes[i] == static_cast<int>(i) + 1);
    CHECK(scene_field("run.model").sweep_axis == 1);
    CHECK(field_help(scene_field("shell.sides")).find("3 to 64") != std::string::npos);
    CHECK(field_help(scene_field("fill.material.preset")).find("bb, rice, peas") != std::string::npos);
    CHECK(field_help(scene_field("run.model")).find("grains, segments, rigid") != std::string::npos);
}

TEST_CASE("the enumerations' names, one list each", "[scene][fields]") {
    // A model's name is its registry row's: the rows' names in their order, then auto (a rule, not a row).
    std::vector<std::string> row_names;
    for (Model m : all_models()) row_names.push_back(model_traits(m).name);
    row_names.emplace_back("auto");
    CHECK(model_names() == row_names);
    for (const char* known : {"grains", "segments", "rigid", "dem3d", "auto"}) CHECK(model_named(known));
    // Every value of the Model enum but automatic has its row (scene.h's enum and the registry agree).
    for (int i = 0; i < static_cast<int>(Model::automatic); ++i) {
        INFO("Model value " << i);
        CHECK_NOTHROW(model_traits(static_cast<Model>(i)));
        CHECK(to_string(static_cast<Model>(i)) != "unknown");
    }
    CHECK(release_pose_names() == std::vector<std::string>{"vertex", "face", "tipped"});
    for (const std::string& n : model_names()) CHECK(to_string(*model_named(n)) == n);
    for (const std::string& n : release_pose_names()) CHECK(to_string(*release_pose_named(n)) == n);
    CHECK(!model_named("fluid"));
}

TEST_CASE("validation messages from the table are the ones the code always gave", "[scene][fields][bad-input]") {
    CHECK(test::scene_error_of(R"({"shell": {"sides": 2}})") == "shell.sides = 2 (from test) is out of range (allowed: 3 to 64)");
    CHECK(test::scene_error_of(R"({"fill": {"ratio": 1.5}})") == "fill.ratio = 1.5 (from test) is out of range (allowed: from 0 to 1)");
    CHECK(test::scene_error_of(R"({"ramp": {"angle_deg": 90}})") ==
          "ramp.angle_deg = 90 (from test) is out of range (allowed: from 0 to 89 degrees)");
    CHECK(test::scene_error_of(R"({"shell": {"wall_thickness_m": 0}})") ==
          "shell.wall_thickness_m = 0 (from test) is out of range (allowed: above 0 to 0.0168 m (at most half of shell.inner_circumradius_m))");
    CHECK(test::scene_error_of(R"({"shell": {"lid_mass_fraction": 1}})") ==
          "shell.lid_mass_fraction = 1 (from test) is out of range (allowed: from 0 to 1, exclusive)");
    CHECK(test::scene_error_of(R"({"run": {"sample_hz": 5000}})") ==
          "run.sample_hz = 5000 (from test) is out of range (allowed: above 0 to 1000 Hz (at most fidelity.step_hz))");
    CHECK(test::scene_error_of(R"({"ramp": {"length_m": 0.1}})").starts_with("ramp.length_m = 0.1 (from test) is out of range (allowed: from 0.1"));
    // A limit that reads another field comes after it: a bad spread is named, not the diameter.
    CHECK(test::scene_error_of(R"({"fill": {"material": {"diameter_spread": -5}}})") ==
          "fill.material.diameter_spread = -5 (from test) is out of range (allowed: from 0 to 0.5)");
    // The checks across fields, after their section.
    CHECK(test::scene_error_of(R"({"shell": {"sides": 64}, "release": {"tilt_deg": 10}})")
              .starts_with("release.tilt_deg = 10 (from test) is too large for n = 64 at 20 degrees"));
    CHECK(test::scene_error_of(R"({"release": {"pose": "edge"}})") == "release.pose = \"edge\" (from test) is not allowed (allowed: vertex, face, tipped)");
    CHECK(test::scene_error_of(R"({"fill": 5})") == "test: fill must be an object with keys ratio, material, got 5");
    CHECK(test::scene_error_of(R"({"fill": {"colour": 5}})") == "test: unknown key 'fill.colour' (allowed: ratio, material)");
    CHECK(test::scene_error_of(R"({"shell": {"sidez": 6}})").starts_with("test: unknown key 'shell.sidez' (allowed: preset, sides, "));
}
