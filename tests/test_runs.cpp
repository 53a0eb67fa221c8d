// Whole grain runs: rest on a level ramp, energy that never grows, grains that stay inside, the
// behaviours, and byte-identical output for identical scenes.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim/grains/bare_engine.h"
#include "sim/files/results_io.h"
#include "sim/grains/world_builder.h"
#include "test_helpers.h"

using namespace polyroll;
using json = nlohmann::ordered_json;

namespace {

// Every grain run in the tests passes through here: the containment check (every grain inside the
// shell at the end) and the energy check (total energy never rises above its value at release by
// more than 0.5% of total mass x g x pivot radius, the scale of one face's potential energy).
RunResult checked_run(const Scene& s) {
    const RunResult r = run_scene(s);
    INFO("scene " << scene_to_json(s).dump());
    INFO("behaviour " << to_string(r.measured.behaviour) << " " << r.measured.divergence);
    REQUIRE(r.measured.behaviour != Behaviour::diverged);
    CHECK(r.measured.grains_inside == r.grains);
    const double energy_scale = (r.shell.mass_kg + r.fill_mass_kg) * s.run.gravity_m_s2 * r.shell.pivot_radius_m;
    CHECK(r.measured.max_energy_gain_J <= 0.005 * energy_scale);
    for (const TrajectorySample& t : r.measured.trajectory) {
        REQUIRE(std::isfinite(t.position_m));
        REQUIRE(std::isfinite(t.kinetic_J));
        // The fill's centre of mass, where a model stepping grains reports it, lies inside the shell.
        REQUIRE(t.fill_ahead_m.has_value() == t.fill_up_m.has_value());
        if (t.fill_ahead_m) {
            CHECK(r.grains > 0);
            CHECK(std::hypot(*t.fill_ahead_m, *t.fill_up_m) < r.shell.pivot_radius_m);
        }
    }
    return r;
}

}  // namespace

TEST_CASE("released on a face on a level ramp, a polygon does not move", "[runs]") {
    for (double fill : {0.0, 0.5}) {
        const Scene s = test::scene_with({{"fill", {{"ratio", fill}}},
                                          {"ramp", {{"angle_deg", 0.0}}},
                                          {"release", {{"pose", "face"}, {"tilt_deg", 0.0}}}});
        const RunResult r = checked_run(s);
        INFO("fill " << fill);
        CHECK(r.measured.behaviour == Behaviour::stopped_at_first_impact);
        CHECK(r.measured.impacts.empty());
        CHECK(std::fabs(r.measured.distance_m) < 1e-4);
        CHECK(r.measured.end_time_s < 2.0);
        // The pile rests on the face below the centre, centred on it, and stays there.
        for (const TrajectorySample& t : r.measured.trajectory) {
            REQUIRE(t.fill_up_m.has_value() == (fill > 0.0));
            if (!t.fill_up_m) continue;
            CHECK(*t.fill_up_m < -0.01);
            CHECK(std::fabs(*t.fill_ahead_m) < 0.002);
        }
    }
}

TEST_CASE("energy never grows and grains stay inside across materials, fills and angles", "[runs]") {
    const json scenes[] = {
        json::object(),  // the default scene
        {{"fill", {{"ratio", 0.5}, {"material", "rice"}}}, {"ramp", {{"angle_deg", 15}}}},
        {{"fill", {{"ratio", 1.0}, {"material", "peas"}}}, {"ramp", {{"angle_deg", 25}}}},
        {{"fill", {{"ratio", 0.375}, {"material", "bb"}}}, {"ramp", {{"preset", "wooden"}, {"angle_deg", 30}}}},
        {{"shell", {{"preset", "hexagon-small"}, {"sides", 18}}}, {"fill", {{"ratio", 0.375}}}, {"ramp", {{"angle_deg", 8}}}},
    };
    for (const json& overrides : scenes) checked_run(test::scene_with(overrides));
}

TEST_CASE("small angles stop at the first impact, steep ones roll to the end", "[runs]") {
    const RunResult shallow = checked_run(test::scene_with({{"fill", {{"ratio", 0.0}}}, {"ramp", {{"angle_deg", 3}}}}));
    CHECK(shallow.measured.behaviour == Behaviour::stopped_at_first_impact);
    CHECK(shallow.measured.impacts.size() == 1);
    CHECK(!shallow.measured.terminal_velocity_m_s);
    CHECK(shallow.measured.stop_time_s.has_value());

    const Scene steep_scene = test::scene_with({{"fill", {{"ratio", 0.0}}}, {"ramp", {{"preset", "wooden"}, {"angle_deg", 12}}}});
    const RunResult steep = checked_run(steep_scene);
    CHECK(steep.measured.behaviour == Behaviour::rolled_to_end);
    REQUIRE(steep.measured.terminal_velocity_m_s);
    CHECK(*steep.measured.terminal_velocity_m_s > 0.0);
    // Distance is the lid centre's travel from release to where the run ends.
    // It ends when the polygon's front reaches the ramp's end: centre at length - outer circumradius.
    const double start_x = release_pose(steep_scene, steep.shell).centre_m.x;
    const double end_x = steep_scene.ramp.length_m - steep.shell.outer_circumradius_m;
    CHECK(steep.measured.distance_m == Approx(end_x - start_x).margin(0.005));
}

TEST_CASE("terminal velocity obeys the rigid model's steady state for an empty shell", "[runs][physics]") {
    // At terminal velocity each face's drop M g s sin(theta) replaces what the impact takes,
    // (1 - Q) KE_before. KE_before is measured, so this checks the tracker's bookkeeping.
    const Scene s = test::scene_with({{"fill", {{"ratio", 0.0}}}, {"ramp", {{"angle_deg", 8}}}});
    const RunResult r = checked_run(s);
    REQUIRE(r.measured.impacts.size() > 20);
    const auto& imp = r.measured.impacts;
    double lost = 0.0;
    for (size_t i = imp.size() - 10; i < imp.size(); ++i) lost += imp[i].kinetic_before_J - imp[i].kinetic_after_J;
    const double drop = r.shell.mass_kg * s.run.gravity_m_s2 * r.shell.outer_side_m *
                        std::sin(s.ramp.angle_deg * 3.14159265358979 / 180.0);
    CHECK(lost / 10.0 == Approx(drop).epsilon(0.03));
}

TEST_CASE("rounded vertices: the shell starts touching, holds on a face, and rolls faster on rounder corners",
          "[runs][vertex]") {
    // Released on a face at 5 deg (below the hexagon's 30 deg tipping angle) it must not move, with any
    // rounding: the arcs are flush with the faces and the pose sinks onto them, so nothing drops.
    for (double radius_m : {0.0001, 0.001}) {
        const Scene held = test::scene_with({{"shell", {{"vertex_radius_m", radius_m}}},
                                             {"fill", {{"ratio", 0.25}}},
                                             {"ramp", {{"angle_deg", 5.0}}},
                                             {"release", {{"pose", "face"}, {"tilt_deg", 0.0}}}});
        const RunResult r = checked_run(held);
        INFO("radius " << radius_m);
        CHECK(r.measured.behaviour == Behaviour::stopped_at_first_impact);
        CHECK(std::fabs(r.measured.distance_m) < 1e-4);
    }
    // Empty hexagon on its vertex at 10 deg: a rounded corner turns the shell from face to face over
    // an arc, so each landing is softer and less is lost; the terminal velocity grows with the radius
    // (measured: 0.248, 0.252, 0.263 m/s at 0.1, 0.25 and 1 mm). The first step must not start with a
    // fall: the rounded vertex is set on the ramp.
    double previous_m_s = 0.0;
    for (double radius_m : {0.0001, 0.00025, 0.001}) {
        const Scene s = test::scene_with({{"shell", {{"vertex_radius_m", radius_m}}},
                                          {"fill", {{"ratio", 0.0}}},
                                          {"ramp", {{"angle_deg", 10.0}}},
                                          {"run", {{"model", "grains"}}}});
        const RunResult r = checked_run(s);
        INFO("radius " << radius_m);
        REQUIRE(r.measured.behaviour == Behaviour::rolled_to_end);
        REQUIRE(r.measured.terminal_velocity_m_s);
        CHECK(*r.measured.terminal_velocity_m_s > previous_m_s);
        previous_m_s = *r.measured.terminal_velocity_m_s;
        REQUIRE(r.measured.trajectory.size() > 2);
        CHECK(std::fabs(r.measured.trajectory[1].speed_m_s) < 0.05);
    }
}

TEST_CASE("the same scene gives byte-identical files, and another seed gives other grains", "[runs][determinism]") {
    const Scene s = test::scene_with({{"fill", {{"ratio", 0.5}, {"material", "peas"}}}, {"ramp", {{"angle_deg", 18}}}});
    const RunResult a = checked_run(s);
    const RunResult b = checked_run(s);
    CHECK(trajectory_csv(a) == trajectory_csv(b));
    CHECK(impacts_csv(a) == impacts_csv(b));
    json sa = summary_json(a), sb = summary_json(b);
    sa["results"].erase("wall_time_s");
    sb["results"].erase("wall_time_s");
    CHECK(sa.dump() == sb.dump());

    Scene other = s;
    other.run.seed = s.run.seed + 1;
    const RunResult c = checked_run(other);
    CHECK(trajectory_csv(c) != trajectory_csv(a));
}

TEST_CASE("trajectory rows come at the sample rate and start at release", "[runs]") {
    const Scene s = test::scene_with({{"fill", {{"ratio", 0.0}}}, {"ramp", {{"angle_deg", 10}}}, {"run", {{"time_limit_s", 1.0}}}});
    const RunResult r = checked_run(s);
    CHECK(r.measured.behaviour == Behaviour::time_limit);
    const auto& t = r.measured.trajectory;
    REQUIRE(t.size() == 31);  // 0, 1/30, ..., 1 s
    CHECK(t.front().time_s == 0.0);
    CHECK(t.front().position_m == 0.0);
    CHECK(t.front().kinetic_J == 0.0);
    CHECK(t[3].time_s == Approx(0.1).margin(1e-3));
    CHECK(t.back().time_s == Approx(1.0).margin(1e-3));
}

TEST_CASE("a run too coarse for its scene is stopped as diverged, with the reason", "[runs][divergence]") {
    // 30 steps a second lets grains fall through the walls while they settle.
    const Scene s = test::scene_with({{"fidelity", {{"step_hz", 30}, {"substeps", 1}}},
                                      {"ramp", {{"angle_deg", 60}}}});
    const RunResult r = run_scene(s);
    CHECK(r.measured.behaviour == Behaviour::diverged);
    CHECK(r.measured.divergence.find("finer fidelity") != std::string::npos);
    CHECK(r.measured.grains_inside < r.grains);
    for (const TrajectorySample& t : r.measured.trajectory) CHECK(std::isfinite(t.position_m));
}

TEST_CASE("a shell nearing the engine's per-step speed limit is stopped as diverged", "[runs][divergence]") {
    // Empty, steep and coarse: 2 cm per step at 60 Hz caps speeds at 1.2 m/s; the shell passes 0.96.
    const Scene s = test::scene_with({{"fill", {{"ratio", 0.0}}},
                                      {"fidelity", {{"step_hz", 60}, {"substeps", 1}}},
                                      {"ramp", {{"angle_deg", 45}}},
                                      {"run", {{"model", "grains"}}}});
    const RunResult r = run_scene(s);
    CHECK(r.measured.behaviour == Behaviour::diverged);
    CHECK(r.measured.divergence.find("engine's limit") != std::string::npos);
}

TEST_CASE("held on a vertex, the whole polygon with its fill is released just past balance", "[runs][release]") {
    for (const char* pose : {"vertex", "tipped"}) {
    for (double fill : {0.25, 0.5, 1.0}) {
        for (const char* material : {"bb", "rice"}) {
            const Scene s = test::scene_with({{"fill", {{"ratio", fill}, {"material", material}}},
                                              {"ramp", {{"angle_deg", 16}}},
                                              {"release", {{"pose", pose}}}});
            auto w = build_world(s);
            double mx = w->shell_props.mass_kg * w->shell->GetPosition().x;
            double my = w->shell_props.mass_kg * w->shell->GetPosition().y, mass = w->shell_props.mass_kg;
            for (const b2Body* b : w->grains) {
                mx += b->GetMass() * b->GetPosition().x;
                my += b->GetMass() * b->GetPosition().y;
                mass += b->GetMass();
            }
            const geom::Vec2 v1 = w->outer_local_m[1];
            const b2Vec2 pivot = w->shell->GetWorldPoint(
                b2Vec2(static_cast<float>(w->units.to_units(v1.x)), static_cast<float>(w->units.to_units(v1.y))));
            const double theta = 16.0 * geom::kPi / 180.0;
            const geom::Vec2 lean = {mx / mass - pivot.x, my / mass - pivot.y};
            const geom::Vec2 up = {-std::sin(theta), std::cos(theta)};
            const double lean_deg = std::atan2(geom::cross(up, lean), geom::dot(up, lean)) * 180.0 / geom::kPi;
            INFO(pose << ", " << material << ", r = " << fill);
            CHECK(lean_deg == Approx(-s.release.tilt_deg).margin(0.02));
        }
    }
    }
    // So a full polygon, which behaves like a solid one, rolls forward rather than tipping back.
    const RunResult full = checked_run(test::scene_with({{"fill", {{"ratio", 1.0}}}, {"ramp", {{"angle_deg", 16}}}}));
    CHECK(full.measured.distance_m > 0.0);
    CHECK(full.measured.behaviour == Behaviour::rolled_to_end);
}

namespace {
// Where the pile's centre of mass lies along face (0, 1), in the shell's frame, from the face's
// middle towards vertex 1 (the pivot), as a share of the face's length.
double pile_offset_along_face(const SimWorld& w) {
    double mx = 0.0, my = 0.0, mass = 0.0;
    for (const b2Body* b : w.grains) {
        const b2Vec2 local = w.shell->GetLocalPoint(b->GetPosition());
        mx += b->GetMass() * w.units.to_m(local.x);
        my += b->GetMass() * w.units.to_m(local.y);
        mass += b->GetMass();
    }
    const geom::Vec2 v0 = w.outer_local_m[0], v1 = w.outer_local_m[1];
    const geom::Vec2 middle = 0.5 * (v0 + v1), along = v1 - v0;
    const geom::Vec2 pile = {mx / mass, my / mass};
    return geom::dot(pile - middle, along) / geom::dot(along, along);
}
}  // namespace

TEST_CASE("the tipped release: the pile settled on the face, then turned onto the vertex with the shell", "[runs][release]") {
    // Octagon three eighths full at 12 deg. Poured with the shell on its face (the face release
    // without a tilt), the pile settles level; the tipped release turns shell and pile together as one
    // body, so in the shell's frame every grain is where it settled on the face. Held on its vertex
    // instead, the pile settles against the downhill walls: another shape.
    for (const char* material : {"bb", "rice"}) {
        auto scene = [&](const char* pose) {
            return test::scene_with({{"shell", "octagon-small"},
                                     {"fill", {{"ratio", 0.375}, {"material", material}}},
                                     {"ramp", {{"angle_deg", 12}}},
                                     {"release", {{"pose", pose}, {"tilt_deg", 0.0}}}});
        };
        const auto face = build_world(scene("face"));
        const auto tipped = build_world(scene("tipped"));
        const auto vertex = build_world(scene("vertex"));
        INFO(material);
        REQUIRE(tipped->grains.size() == face->grains.size());
        double farthest_m = 0.0;
        for (size_t i = 0; i < face->grains.size(); ++i) {
            const b2Vec2 a = face->shell->GetLocalPoint(face->grains[i]->GetPosition());
            const b2Vec2 b = tipped->shell->GetLocalPoint(tipped->grains[i]->GetPosition());
            farthest_m = std::max(farthest_m, tipped->units.to_m((a - b).Length()));
        }
        CHECK(farthest_m < 1e-5);
        // The shell stands on its vertex: turned from the face by at least the balance turn.
        const double balance_turn_rad = geom::kPi / 8.0 - 12.0 * geom::kPi / 180.0;
        CHECK(-tipped->shell->GetAngle() > 0.9 * balance_turn_rad);
        CHECK(std::abs(pile_offset_along_face(*tipped) - pile_offset_along_face(*vertex)) > 0.05);
    }
    // An empty shell has nothing to pour: the tipped release is the vertex release, run for run.
    const RunResult empty_vertex = checked_run(test::scene_with({{"fill", {{"ratio", 0.0}}}, {"run", {{"model", "grains"}}}}));
    const RunResult empty_tipped = checked_run(test::scene_with(
        {{"fill", {{"ratio", 0.0}}}, {"run", {{"model", "grains"}}}, {"release", {{"pose", "tipped"}}}}));
    CHECK(empty_tipped.measured.distance_m == empty_vertex.measured.distance_m);
    CHECK(empty_tipped.measured.trajectory.size() == empty_vertex.measured.trajectory.size());
}

TEST_CASE("one disc per grain: energy never created and every disc stays inside", "[runs]") {
    // 251 discs of 1.8 mm (the engine's 1 mm unit) in the default scene: 2 s covers the pour's
    // settling, the release and several face impacts.
    const Scene s = test::scene_with({{"fill", {{"material", {{"grains_per_disc", 1.0}}}}}, {"run", {{"time_limit_s", 2.0}}}});
    const RunResult r = checked_run(s);
    CHECK(r.grains > 200);
    CHECK(!r.measured.impacts.empty());
}

// polyroll bench --scaling reads the engine's load through measure_engine_load: the grains it built,
// a time spent stepping, and Box2D's contacts split into touching and merely near (their enlarged
// boxes overlapping). The large hexagon's smaller discs (a deeper box: sim/geometry/disc_size.h) sit closer
// to one another than Box2D's fixed margin, so each disc keeps more contacts there: the measured
// reason its grains cost more each (docs/engine-cost.md).
TEST_CASE("the engine's load: grains, contacts near and touching, per disc", "[runs][bench]") {
    // Box2D's own contacts (fidelity.contacts boxes); near contacts below.
    const Scene small = test::scene_with(json::parse(R"({"run": {"model": "grains"}, "fidelity": {"contacts": "boxes"}})"));
    const EngineLoad a = measure_engine_load(small, 300);
    CHECK(a.grains == 143);  // the default scene: 124 discs at a level of r, 143 at 1.15 r (closure pile-bulk)
    CHECK(a.wall_s > 0.0);
    CHECK(a.touching_per_grain > 0.5);
    CHECK(a.contacts_per_grain > 2.0 * a.touching_per_grain);
    CHECK(a.shell_speed_m_s == Approx(0.0).margin(1e-3));  // timed from the release, at rest
    // Stepped untimed to 0.25 s, before the first landing: the shell is then turning down its vertex.
    const EngineLoad later = measure_engine_load(small, 50, 250);
    CHECK(later.grains == a.grains);
    CHECK(later.shell_speed_m_s > 0.1);

    const char* large_json =
        R"({"shell": {"preset": "hexagon-large"}, "fill": {"ratio": 0.5}, "run": {"model": "grains"}, "fidelity": {"contacts": "boxes"}})";
    const Scene large = test::scene_with(json::parse(large_json));
    const EngineLoad b = measure_engine_load(large, 300);
    CHECK(b.grains > 1400);
    CHECK(b.contacts_per_grain > 1.3 * a.contacts_per_grain);
    // Touching contacts per disc are a property of the packing, about the same in both piles.
    CHECK(b.touching_per_grain == Approx(a.touching_per_grain).epsilon(0.5));

    // Near contacts (sim/grains/near_pairs.h): the touching pairs and the few within Box2D's slop of
    // touching, as many a disc in the big pile as in the small one.
    Scene small_near = small, large_near = large;
    small_near.fidelity.contacts = large_near.fidelity.contacts = GrainContacts::near;
    const EngineLoad an = measure_engine_load(small_near, 300), bn = measure_engine_load(large_near, 300);
    CHECK(an.contacts_per_grain < 0.6 * a.contacts_per_grain);
    CHECK(bn.contacts_per_grain < 0.6 * b.contacts_per_grain);
    CHECK(bn.contacts_per_grain == Approx(an.contacts_per_grain).epsilon(0.3));
    CHECK(bn.touching_per_grain == Approx(b.touching_per_grain).epsilon(0.5));
}
