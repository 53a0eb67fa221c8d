// The reduced models on a curved track (ramp_profile.h): the rigid polygon and the segments take the
// local slope at the pivot, the free body the slope under its centre, and `--model auto` runs empty
// and full shells there with them; measured against the grain engine's empty shell on the same track.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "sim/model_choice.h"
#include "sim/model_registry.h"
#include "sim/reduced/reduced_models.h"
#include "sim/reduced/rolling_polygon.h"
#include "sim/files/results_io.h"
#include "test_helpers.h"

using namespace polyroll;

namespace {

// The reduced models' vertices are sharp: the grain engine's shell is made as sharp as it makes one
// (its skin), so the two compare like with like.
Scene shell_on_track(const char* shell, double fill, double angle_deg, double curvature_deg_per_m, Model model) {
    return test::with_model(test::scene_with({{"shell", {{"preset", shell}, {"vertex_radius_m", 0.0}}},
                                              {"fill", {{"ratio", fill}, {"material", "bb"}}},
                                              {"ramp", {{"angle_deg", angle_deg},
                                                        {"curvature_deg_per_m", curvature_deg_per_m}}}}),
                            model);
}

}  // namespace

TEST_CASE("curved track: every model may run it, and auto picks the reduced models for empty and full shells",
          "[ramp_profile][curved][auto]") {
    for (Model m : all_models()) CHECK(model_traits(m).follows_curved_track);
    for (const char* model : {"rigid", "segments", "grains"}) {
        INFO(model);
        const std::string doc = std::string(R"({"fill": {"ratio": 0.25}, "ramp": {"curvature_deg_per_m": 1.7}, )") +
                                R"("run": {"model": ")" + model + "\"}}";
        CHECK(test::scene_error_of(doc).empty());
    }
    for (double curvature : {0.0, 1.7}) {
        INFO("curvature " << curvature);
        for (double fill : {0.0, 1.0}) {
            INFO("fill " << fill);
            const ModelChoice c = choose_model(shell_on_track("octagon-small", fill, 10.0, curvature, Model::automatic));
            CHECK(c.model == Model::rigid);
            REQUIRE(c.then);
            CHECK(*c.then == Model::grains);
            CHECK_THAT(c.reason, Catch::Contains(fill == 0.0 ? "empty shell" : "full shell"));
        }
        CHECK(choose_model(shell_on_track("octagon-small", 0.375, 10.0, curvature, Model::automatic)).model ==
              Model::grains);
    }
}

TEST_CASE("curved track: curvature 0 is the straight track to the bit, and a vanishing one tends to it",
          "[ramp_profile][curved][models]") {
    for (Model m : {Model::rigid, Model::segments}) {
        const Scene straight = shell_on_track("hexagon-small", 0.375, 12.0, 0.0, m);
        // The frame the models ran on before the track could curve: no profile at all.
        models::RampFrame bare = models::ramp_frame(straight);
        bare.curvature_deg_per_m = 0.0;
        bare.track_length_m = 0.0;
        const models::FillMotion motion = m == Model::rigid ? models::FillMotion::frozen : models::FillMotion::relevel;
        const models::RollingRun a = models::roll(models::rolling_body(straight), motion, bare);
        const RunResult b = run_scene(straight);
        REQUIRE(a.measured.trajectory.size() == b.measured.trajectory.size());
        CHECK(trajectory_csv(b) == trajectory_csv([&] {
                  RunResult r = b;
                  r.measured = a.measured;
                  return r;
              }()));
        // The curved track's own arithmetic (its height, a slope per pivot) at 1e-5 deg/m: the
        // straight run to the precision that curvature leaves.
        Scene tiny = straight;
        tiny.ramp.curvature_deg_per_m = 1e-5;
        const RunResult c = run_scene(tiny);
        INFO(to_string(m));
        CHECK(c.measured.behaviour == b.measured.behaviour);
        CHECK(c.measured.impacts.size() == b.measured.impacts.size());
        CHECK(c.measured.distance_m == Approx(b.measured.distance_m).epsilon(1e-5));
        CHECK(c.measured.trajectory.back().potential_J ==
              Approx(b.measured.trajectory.back().potential_J).epsilon(1e-5));
    }
}

namespace {

// A run's speed and energy at the end, and how it ended, as the comparisons below read them.
struct Outcome {
    Behaviour behaviour = Behaviour::running;
    double distance_m = 0.0;
    std::optional<double> terminal_m_s;
    double dissipated_J = 0.0;
};

Outcome outcome_of(const RunResult& r) {
    return {r.measured.behaviour, r.measured.distance_m, r.measured.terminal_velocity_m_s,
            r.measured.trajectory.empty() ? 0.0 : r.measured.trajectory.back().dissipated_J};
}

// The same behaviour; the terminal velocity within 3% (the straight track's impact ratios agree within
// 3%, "an empty shell rolls alike in the rigid model and the grain simulation"); a stop within 5% of
// the distance or half a side, whichever is more; the energy dissipated by the end within 5% (both
// book the track's own potential).
void check_alike(const Outcome& model, const Outcome& grains, double side_m, double vt_share = 0.03,
                 double dissipated_share = 0.05) {
    INFO("behaviour " << to_string(model.behaviour) << " / " << to_string(grains.behaviour) << ", D "
                      << model.distance_m << " / " << grains.distance_m << " m, Vt "
                      << model.terminal_m_s.value_or(-1.0) << " / " << grains.terminal_m_s.value_or(-1.0)
                      << " m/s, dissipated " << model.dissipated_J << " / " << grains.dissipated_J << " J");
    REQUIRE(model.behaviour == grains.behaviour);
    if (model.behaviour == Behaviour::rolled_to_end) {
        REQUIRE(model.terminal_m_s);
        REQUIRE(grains.terminal_m_s);
        CHECK(*model.terminal_m_s == Approx(*grains.terminal_m_s).epsilon(vt_share));
    } else {
        CHECK(std::fabs(model.distance_m - grains.distance_m) <=
              std::max(0.05 * grains.distance_m, 0.5 * side_m));
    }
    CHECK(model.dissipated_J == Approx(grains.dissipated_J).epsilon(dissipated_share));
}

}  // namespace

TEST_CASE("curved track: the rigid model's empty shell behaves as the grain engine's on a track sagging 1.7 deg/m",
          "[ramp_profile][curved][models]") {
    struct Case {
        const char* shell;
        double angle_deg;
    };
    // Angles either side of where each empty shell passes its first impact on this track, and two
    // that roll to the end without lifting off.
    for (const Case& c : {Case{"hexagon-small", 5.0}, Case{"hexagon-small", 10.0}, Case{"octagon-small", 3.0},
                          Case{"octagon-small", 8.0}}) {
        INFO(c.shell << " at " << c.angle_deg << " deg");
        const Scene s = shell_on_track(c.shell, 0.0, c.angle_deg, 1.7, Model::rigid);
        const RunResult rigid = run_scene(s);
        const RunResult grains = run_scene(test::with_model(s, Model::grains));
        REQUIRE(rigid.model_valid);
        check_alike(outcome_of(rigid), outcome_of(grains), rigid.shell.outer_side_m);
        // Gravity held at the pivot's slope would do a little more work than the track's height
        // falls (about the centre's height x curvature, 1e-3 of the drop, adding up face after face);
        // the model turns it so the books close at every landing (rolling_polygon.cpp,
        // face_work_up). What is left is the swing within a face: below 1e-4 of the height fallen
        // (measured 0.7-3.7e-5; 9e-4 for the hexagon at 10 deg before the turn).
        const double fallen_J = -rigid.measured.trajectory.back().potential_J;
        REQUIRE(fallen_J > 0.0);
        CHECK(rigid.measured.max_energy_gain_J < 1e-4 * fallen_J);
    }
}

namespace {

// The scene run by `auto`, which must pick the rigid model and run no grains, and by the grain engine.
std::pair<RunResult, RunResult> auto_and_grains(const Scene& s) {
    RunResult a = run_scene(s);
    REQUIRE(a.model_choice);
    CHECK(a.model_choice->model == Model::rigid);
    CHECK(model_that_ran(a) == Model::rigid);
    CHECK(a.grains == 0);
    return {std::move(a), run_scene(test::with_model(s, Model::grains))};
}

// The mean terminal velocity and energy dissipated of runs that each rolled to the end.
Outcome mean_of_rolls(const std::vector<Outcome>& runs) {
    Outcome mean;
    mean.behaviour = Behaviour::rolled_to_end;
    mean.terminal_m_s = 0.0;
    const double n = static_cast<double>(runs.size());
    for (const Outcome& o : runs) {
        REQUIRE(o.behaviour == Behaviour::rolled_to_end);
        REQUIRE(o.terminal_m_s);
        *mean.terminal_m_s += *o.terminal_m_s / n;
        mean.dissipated_J += o.dissipated_J / n;
    }
    return mean;
}

}  // namespace

TEST_CASE("curved track: auto runs empty and full shells with the reduced models as the grain engine runs them",
          "[ramp_profile][curved][auto][slow]") {
    // A full hexagon rolling down without lifting off: the rigid model once, the grain engine at seeds
    // 1 to 3, compared with their mean. A full shell's Box2D discs rattle in their packing at every
    // impact (docs/studies/full-shells.md), which the rigid polygon leaves out, and how much depends on
    // the packing: measured 2026-12-02, the rigid model 0.222 m/s, the grain engine 0.191-0.210 m/s
    // over seeds 1 to 5 (mean 0.201; the same spread in the ramp's frame and the pile's), so its
    // three-seed mean is about 10% slower, and 15% is allowed. One seed alone may lie 14% below.
    {
        Scene s = shell_on_track("hexagon-small", 1.0, 12.0, 1.7, Model::automatic);
        const auto [a, g] = auto_and_grains(s);  // the grain engine at seed 1
        std::vector<Outcome> grains{outcome_of(g)};
        for (std::uint64_t seed = 2; seed <= 3; ++seed) {
            s.run.seed = seed;
            INFO("full hexagon, grain engine seed " << seed);
            grains.push_back(outcome_of(run_scene(test::with_model(s, Model::grains))));
        }
        check_alike(outcome_of(a), mean_of_rolls(grains), a.shell.outer_side_m, 0.15);
    }
    // An empty octagon at 25 deg hops down the lower track (the rigid model goes on as a free body):
    // a bouncing run is chaotic, and a twentieth of a degree moves the energy it loses by 10-35% in
    // either model (measured at 24.9-25.1 deg), so one angle compares luck. Five angles a twentieth
    // of a degree apart: the same behaviour at each, and the means within what their spread allows
    // (measured 2026-11-28: Vt 3% apart, the energy dissipated 10%; grain engine's spread 0.13-0.20 J).
    std::vector<Outcome> models, grains;
    double side_m = 0.0;
    for (int i = 0; i < 5; ++i) {
        const double angle_deg = 24.9 + 0.05 * i;
        INFO("octagon-small fill 0 at " << angle_deg << " deg");
        const Scene s = shell_on_track("octagon-small", 0.0, angle_deg, 1.7, Model::automatic);
        const auto [a, g] = auto_and_grains(s);
        models.push_back(outcome_of(a));
        grains.push_back(outcome_of(g));
        side_m = a.shell.outer_side_m;
    }
    check_alike(mean_of_rolls(models), mean_of_rolls(grains), side_m, 0.05, 0.15);
}
