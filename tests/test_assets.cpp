// The bundled presets: every file parses, every value says where it comes from, and the presets the
// experiment needs are there.
#include <catch2/catch.hpp>

#include "sim/assets.h"
#include "sim/model_choice.h"
#include "sim/scene/scene_json.h"

using namespace polyroll;

TEST_CASE("every preset value has a source", "[assets]") {
    using assets::Kind;
    for (Kind k : assets::all_kinds()) {
        for (const std::string& name : assets::preset_names(k)) {
            const auto& entry = assets::preset_entry(k, name);
            REQUIRE(entry.contains("description"));
            REQUIRE(entry.contains("values"));
            REQUIRE(entry.contains("sources"));
            for (const auto& [key, value] : entry.at("values").items()) {
                INFO(assets::kind_file(k) << ": " << name << "." << key);
                REQUIRE(entry.at("sources").contains(key));
                CHECK(entry.at("sources").at(key).get<std::string>().size() > 8);
            }
            // And no source for a value that does not exist (a stale note).
            for (const auto& [key, value] : entry.at("sources").items()) {
                INFO(name << ": source for missing value " << key);
                CHECK(entry.at("values").contains(key));
            }
        }
    }
}

TEST_CASE("the experiment's presets are bundled", "[assets]") {
    using assets::Kind;
    for (const char* n : {"hexagon-small", "octagon-small", "decagon-small", "octadecagon-small", "hexagon-large"})
        CHECK_NOTHROW(assets::preset_values(Kind::polygon, n));
    for (const char* n : {"bb", "rice", "peas"}) CHECK_NOTHROW(assets::preset_values(Kind::material, n));
    for (const char* n : {"air-track", "wooden"}) CHECK_NOTHROW(assets::preset_values(Kind::ramp, n));
    for (const char* n : {"draft", "standard", "precise", "reference"})
        CHECK_NOTHROW(assets::preset_values(Kind::fidelity, n));
}

TEST_CASE("every default of the default scene has a source", "[assets]") {
    const auto& defaults = assets::file("defaults.json");
    const auto& sources = defaults.at("sources");
    for (const auto& [section, body] : defaults.at("scene").items()) {
        if (sources.contains(section)) continue;  // the whole section has one source
        for (const auto& [key, v] : body.items()) {
            INFO(section << "." << key);
            CHECK(sources.contains(section + "." + key));
        }
    }
}

TEST_CASE("the default scene is Fig. 7's: small hexagon, BBs, r = 0.25, air track, 20 degrees", "[assets]") {
    const Scene s = resolve_scene({});
    CHECK(s.shell.preset == "hexagon-small");
    CHECK(s.shell.sides == 6);
    CHECK(s.fill.material.preset == "bb");
    CHECK(s.fill.ratio == 0.25);
    CHECK(s.ramp.preset == "air-track");
    CHECK(s.ramp.angle_deg == 20.0);
    CHECK(s.release.pose == ReleasePose::vertex);
    CHECK(s.fidelity.preset == "standard");
    // Model only what the scene requires: auto, which for this filled shell is the grain simulation.
    CHECK(s.run.model == Model::automatic);
    CHECK(choose_model(s).model == Model::grains);
    CHECK(!choose_model(s).then);
    CHECK(s.run.sample_hz == 30.0);
}
