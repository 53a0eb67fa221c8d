// The 3D reference (--model dem3d): its input, the measurement of its recorded states by the
// tracker's rules, a saved Yade output measured again, and one short real run in Yade.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim/dem3d/dem3d_input.h"
#include "sim/dem3d/dem3d_run.h"
#include "sim/dem3d/state_tracker.h"
#include "sim/reduced/reduced_models.h"
#include "sim/files/results_io.h"
#include "sim/geometry/fill_spheres.h"
#include "sim/geometry/shell_properties.h"
#include "test_helpers.h"

using namespace polyroll;
using namespace polyroll::dem3d;
using json = nlohmann::ordered_json;

namespace {

// The rows a rigid polygon rolling without slipping gives at every tracker step: the rigid model's
// run sampled at the step rate, each sample turned into the shell's state.
std::vector<StateRow> rigid_rows(const Scene& scene, RunResult& rigid) {
    Scene fine = scene;
    fine.run.sample_hz = scene.fidelity.step_hz;
    rigid = models::run_reduced_model(fine, models::FillMotion::frozen);
    std::vector<StateRow> rows;
    for (const TrajectorySample& t : rigid.measured.trajectory) {
        StateRow r;
        r.time_s = t.time_s;
        r.shell = rolling_state(scene, t);
        r.kinetic_J = t.kinetic_J;
        r.potential_J = t.potential_J;
        rows.push_back(r);
    }
    return rows;
}

TrackRules rigid_rules(const Scene& scene) {
    const ShellProperties p = shell_properties(scene.shell);
    TrackRules rules;
    rules.energy_scale_J = p.mass_kg * scene.run.gravity_m_s2 * p.pivot_radius_m;
    rules.contact_tolerance_m = 0.0005;
    return rules;
}

}  // namespace

TEST_CASE("dem3d's input: the 2D models' pose, end and the fill's grain count", "[dem3d]") {
    const Scene s = test::scene_with(json::object());
    const json in = script_input(s, 30.0);
    const ShellProperties p = shell_properties(s.shell);
    // The small hexagon a quarter full of 6 mm BBs: r x inside volume x packing / grain volume.
    CHECK(fill_sphere_count(s) == 241);
    CHECK(in["fill"]["grain_count"] == 241);
    CHECK(in["fill"]["grain_density_kg_m3"].get<double>() == Approx(1060.0 / 0.6));
    CHECK(in["shell"]["outer_vertices_m"].size() == 6);
    CHECK(in["end_centre_x_m"].get<double>() == Approx(s.ramp.length_m - p.outer_circumradius_m));
    CHECK(in["release"]["angle_rad"].get<double>() == Approx(release_pose(s, p).angle_rad));
    CHECK(in["release"]["tip_rad"].get<double>() == 0.0);
    CHECK(in["dem3d"]["contact_time_s"].get<double>() == Approx(0.001));
    // The edge spheres are the shell's own vertex rounding, the value Box2D's arcs take.
    CHECK(in["dem3d"]["edge_radius_m"].get<double>() == s.shell.vertex_radius_m);
    CHECK(s.shell.vertex_radius_m == Approx(0.00025));
    // The tipped release: poured with the shell flat on its face, then turned by tip_rad onto the vertex.
    const Scene tipped = test::scene_with({{"release", {{"pose", "tipped"}}}});
    const json tipped_in = script_input(tipped, 30.0);
    CHECK(tipped_in["release"]["pose"] == "tipped");
    CHECK(tipped_in["release"]["angle_rad"].get<double>() == 0.0);
    CHECK(tipped_in["release"]["centre_m"][1].get<double>() == Approx(p.outer_apothem_m));
    CHECK(tipped_in["release"]["tip_rad"].get<double>() == Approx(release_pose(tipped, p).angle_rad));
    CHECK(release_pose(tipped, p).angle_rad == Approx(release_pose(s, p).angle_rad));
    CHECK(fill_sphere_count(test::scene_with({{"fill", {{"ratio", 0.0}}}})) == 0);
}

TEST_CASE("dem3d's tracker measures a rigid polygon's states as the rigid model does", "[dem3d]") {
    // The rigid model's own impacts and behaviour are the yardstick: the rows carry only the states,
    // and the tracker must find every face landed, within a step, and the same ending.
    for (double angle : {8.0, 20.0}) {
        INFO("angle " << angle);
        const Scene s = test::scene_with({{"fill", {{"ratio", 0.0}}}, {"ramp", {{"angle_deg", angle}}}});
        RunResult rigid;
        const std::vector<StateRow> rows = rigid_rows(s, rigid);
        const Measurements m = measure_states(s, rows, rigid_rules(s));
        CHECK(to_string(m.behaviour) == to_string(rigid.measured.behaviour));
        REQUIRE(m.impacts.size() == rigid.measured.impacts.size());
        const double step_s = 1.0 / s.fidelity.step_hz;
        for (size_t i = 0; i < m.impacts.size(); ++i) {
            CHECK(m.impacts[i].time_s >= rigid.measured.impacts[i].time_s - 1e-9);
            CHECK(m.impacts[i].time_s <= rigid.measured.impacts[i].time_s + step_s + 1e-9);
            // The energy after is read where the rigid body has already turned onto its new pivot.
            CHECK(m.impacts[i].ratio() == Approx(rigid.measured.impacts[i].ratio()).epsilon(0.05));
        }
        if (rigid.measured.terminal_velocity_m_s) {
            REQUIRE(m.terminal_velocity_m_s);
            CHECK(*m.terminal_velocity_m_s == Approx(*rigid.measured.terminal_velocity_m_s).epsilon(0.01));
        }
        CHECK(m.distance_m == Approx(rigid.measured.distance_m).margin(0.01));
        // The trajectory at the scene's sampling rate, and the delayed readings 3 ms after each landing.
        CHECK(m.trajectory.size() >= static_cast<size_t>(m.end_time_s * s.run.sample_hz));
        for (const FaceImpact& f : m.impacts)
            if (f.time_s + kKineticDelay_s < m.end_time_s) CHECK(f.kinetic_delayed_J);
    }
}

TEST_CASE("dem3d's tracker: a grain leaving the box, energy created or a NaN end the run as diverged", "[dem3d]") {
    const Scene s = test::scene_with({{"fill", {{"ratio", 0.0}}}, {"ramp", {{"angle_deg", 20.0}}}});
    RunResult rigid;
    std::vector<StateRow> rows = rigid_rows(s, rigid);
    REQUIRE(rows.size() > 500);
    TrackRules rules = rigid_rules(s);
    {
        std::vector<StateRow> bad = rows;
        bad[300].shell.velocity_m_s.x = NAN;
        const Measurements m = measure_states(s, bad, rules);
        CHECK(m.behaviour == Behaviour::diverged);
        CHECK(m.divergence.find("t = 0.3000 s") != std::string::npos);
    }
    {
        std::vector<StateRow> bad = rows;
        for (size_t i = 200; i < bad.size(); ++i) bad[i].kinetic_J += 10.0;
        const Measurements m = measure_states(s, bad, rules);
        CHECK(m.behaviour == Behaviour::diverged);
        CHECK(m.divergence.find("energy rose") != std::string::npos);
    }
    {
        rules.grains = 5;
        std::vector<StateRow> bad = rows;
        for (size_t i = 0; i < bad.size(); ++i) bad[i].grains_inside = i < 400 ? 5 : 4;
        const Measurements m = measure_states(s, bad, rules);
        CHECK(m.behaviour == Behaviour::diverged);
        CHECK(m.divergence.find("1 of 5 grains left the box") != std::string::npos);
    }
}

TEST_CASE("dem3d's states.csv: malformed rows are refused naming the line", "[dem3d]") {
    const std::string header = "time_s,x_m,y_m,angle_rad,vx_m_s,vy_m_s,omega_rad_s,kinetic_J,potential_J,"
                               "fill_ahead_m,fill_up_m,grains_inside\n";
    const std::vector<StateRow> one = parse_states_csv(header + "0,1,2,3,4,5,6,7,8,9,10,11\n");
    REQUIRE(one.size() == 1);
    CHECK(one[0].fill_offset_m.x == 9.0);
    CHECK(one[0].fill_offset_m.y == 10.0);
    CHECK(one[0].grains_inside == 11);
    CHECK_THROWS_WITH(parse_states_csv("time_s\n"), Catch::Contains("header"));
    CHECK_THROWS_WITH(parse_states_csv(header + "0,1,2,3,4,5,6,7,8,9,10,11\n0,1,2,x,4,5,6,7,8,9,10,11\n"),
                      Catch::Contains("line 3") && Catch::Contains("'x'"));
    CHECK_THROWS_WITH(parse_states_csv(header + "0,1,2,3\n"), Catch::Contains("line 2") && Catch::Contains("4 columns"));
    CHECK_THROWS_WITH(parse_states_csv(header + "0,1,2,3,4,5,6,7,8,9,10,11,12\n"), Catch::Contains("line 2"));
    const std::vector<GrainFrame> frames =
        parse_grains_csv("time_s,grain,x_m,y_m,z_m,radius_m\n0,0,1,2,-0.031,0.003\n0,1,1,2,0.031,0.003\n"
                         "0.1,0,1,2,0,0.003\n",
                         0.062);
    REQUIRE(frames.size() == 2);
    CHECK(frames[0].grains.size() == 2);
    CHECK(frames[0].grains[0].depth == Approx(0.0));
    CHECK(frames[0].grains[1].depth == Approx(1.0));
    CHECK(frames[1].grains[0].depth == Approx(0.5));
    CHECK_THROWS_WITH(parse_grains_csv("time_s,grain,x_m,y_m,z_m,radius_m\n0,0,1\n", 0.062), Catch::Contains("line 2"));
}

TEST_CASE("dem3d: a saved Yade output is read and measured as the run that wrote it", "[dem3d]") {
    // tests/data/dem3d: what polyroll_dem3d.py wrote for the small hexagon a quarter full of BBs at 14
    // deg, seed 1 (states.csv, setup.json, IN.json and the first two frames of grains.csv). That run
    // stopped at its first impact 0.026 m down the ramp, all 241 grains inside.
    const std::filesystem::path dir = std::filesystem::path(POLYROLL_SOURCE_DIR) / "tests" / "data" / "dem3d";
    // That run's edge spheres were 1 mm.
    const Scene s = test::with_model(test::scene_with({{"shell", {{"preset", "hexagon-small"}, {"vertex_radius_m", 0.001}}},
                                                       {"ramp", {{"angle_deg", 14.0}}}}),
                                     Model::dem3d);
    // The saved input is what this scene gives the script today.
    CHECK(json::parse(test::read_file(dir / "IN.json")) == script_input(s, s.run.sample_hz));
    const Dem3dOutput out = read_output(s, dir);
    const Measurements& m = out.result.measured;
    CHECK(m.behaviour == Behaviour::stopped_at_first_impact);
    CHECK(m.distance_m == Approx(0.0261).margin(0.0005));
    REQUIRE(m.impacts.size() == 1);
    CHECK(m.impacts[0].ratio() > 0.0);
    REQUIRE(m.impacts[0].kinetic_delayed_J);
    CHECK(*m.impacts[0].kinetic_delayed_J < m.impacts[0].kinetic_after_J);
    CHECK(m.grains_inside == 241);
    CHECK(out.result.grains == 241);
    CHECK(out.result.fill_mass_kg == Approx(0.0481).epsilon(0.01));
    CHECK(out.result.model_blocks.json()["dem3d_engine"]["yade_version"] == "2023.02a");
    CHECK(m.stop_time_s);
    CHECK(m.trajectory.front().position_m == 0.0);
    // Released on its vertex, the quarter-full pile lies below the shell's centre, near the axis
    // through the pivot (the small hexagon's inside radius is about 3.6 cm).
    REQUIRE(m.trajectory.front().fill_up_m);
    CHECK(*m.trajectory.front().fill_up_m < -0.01);
    CHECK(*m.trajectory.front().fill_up_m > -0.036);
    CHECK(std::fabs(*m.trajectory.front().fill_ahead_m) < 0.01);
    REQUIRE(out.frames.size() == 2);
    CHECK(out.frames[0].grains.size() == 241);
    CHECK(out.frames[1].time_s == Approx(1.0 / 30.0).margin(1e-3));
    // A missing file is named.
    CHECK_THROWS_WITH(read_output(s, dir / "nowhere"), Catch::Contains("states.csv"));
}

TEST_CASE("dem3d in Yade: the same seed gives the same run, revealed step by step as run_scene gives it", "[dem3d][yade]") {
    // The small hexagon a quarter full at 14 deg stops at its first impact: about 4 CPU-seconds.
    const Scene s = test::with_model(test::scene_with({{"ramp", {{"angle_deg", 14.0}}}}), Model::dem3d);
    const RunResult a = run_scene(s);
    const RunResult b = run_scene(s);
    CHECK(a.measured.behaviour == Behaviour::stopped_at_first_impact);
    CHECK(a.grains == 241);
    CHECK(a.measured.grains_inside == 241);
    CHECK(a.settled);
    CHECK(trajectory_csv(a) == trajectory_csv(b));
    CHECK(impacts_csv(a) == impacts_csv(b));
    REQUIRE(a.measured.impacts.size() == 1);
    // The delayed reading is after the contact's own loss: below the reading at the landing step.
    REQUIRE(a.measured.impacts[0].kinetic_delayed_J);
    CHECK(*a.measured.impacts[0].kinetic_delayed_J < a.measured.impacts[0].kinetic_before_J);

    // Stepped in the tracker's steps, with the grains drawn from the recorded frames, and replayed
    // without running Yade again.
    std::unique_ptr<ModelRun> run = start_run(s);
    CHECK(run->grains() == 241);
    while (run->step()) {
        if (run->steps() % 100 == 0) {
            const RunSnapshot snap = run->snapshot();
            CHECK(snap.grains.size() == 241);
            for (const GrainState& g : snap.grains) CHECK((g.depth >= 0.0 && g.depth <= 1.0));
            // The snapshot's reading is the trajectory's, the fill's offset included.
            REQUIRE(snap.now.fill_up_m);
            CHECK(*snap.now.fill_up_m < 0.0);
        }
    }
    CHECK(impacts_csv(run->result()) == impacts_csv(a));
    std::unique_ptr<ModelRun> again = run->replay();
    REQUIRE(again);
    CHECK(again->steps() == 0);
    CHECK(again->measured().impacts.empty());
    again->run_to_end();
    CHECK(again->steps() == run->steps());
    CHECK(again->measured().impacts.size() == 1);
}
