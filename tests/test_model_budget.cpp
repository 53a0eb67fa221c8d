// The sandbox's physics budget: which cheaper model it offers when the scenes asked for cannot keep
// real time, that coarser grains keep the fill's mass, that the window steps only what the user
// picked (a slow machine plays the same run slower), and what the panel says. Figures are set here (not the asset's measured ones), so the choices
// do not depend on the machine the asset was measured on.
#include <catch2/catch.hpp>

#include <cmath>

#include <fmt/format.h>

#include "sim/geometry/disc_size.h"
#include "app/model_budget.h"
#include "app/readouts.h"
#include "app/sandbox_physics.h"
#include "sim/grains/fill_plan.h"
#include "sim/scene/scene_validate.h"
#include "test_helpers.h"

using namespace polyroll;
using namespace polyroll::app;
using json = nlohmann::ordered_json;

namespace {

// The asset's levels and errors, with a chosen cost and share.
BudgetFigures figures(double s_per_cost_unit) {
    BudgetFigures f = budget_figures();
    f.cost.engine_step_s = s_per_cost_unit;
    f.physics_share = 0.7;
    f.cost.packing = 0.9;
    // Linear at the scenes' own 15 iterations, so a lane of G grains costs G + 1 units a step and the
    // thresholds below are plain sums.
    f.cost.engine_exponent = 1.0;
    f.cost.engine_reference_iterations = 15.0;
    return f;
}

// The large hexagon full of rice, every grain stepped (under auto a full shell is one rigid body).
Scene big_rice() {
    return test::with_model(
        test::scene_with({{"shell", "hexagon-large"}, {"fill", {{"ratio", 1.0}, {"material", "rice"}}}}), Model::grains);
}

double fill_mass_kg(const Scene& s) {
    const FillPlan plan = plan_fill(s, shell_properties(s.shell), {0.0, 1.0});
    double mass = 0.0;
    for (const PlannedGrain& g : plan.grains) mass += g.mass_kg;
    return mass;
}

}  // namespace

TEST_CASE("the budget keeps a cheap scene as asked and makes an expensive one cheaper, nearest first",
          "[app][budget]") {
    const std::vector<Scene> big = {big_rice()};
    const double grains = 0.9 * estimated_grain_count(big[0]);
    REQUIRE(grains > 900);

    SECTION("a reduced model or an empty shell fits any budget") {
        const BudgetFigures f = figures(3e-6);
        for (const Scene& s : {test::with_model(big_rice(), Model::rigid), test::scene_with({{"fill", {{"ratio", 0.0}}}})}) {
            const BudgetChoice c = offered_level({s}, f, f.cost.engine_step_s, false);
            CHECK(!c.reduced());
            CHECK(c.fits);
            CHECK(apply_choice({s}, f, c)[0].fill.material.diameter_m == s.fill.material.diameter_m);
        }
    }
    SECTION("a full shell under auto steps no grains until it is handed over, and the panel says so") {
        const BudgetFigures f = figures(0.7 / (grains * 1000.0) * 4.0);  // the grains four times too slow
        const Scene full_auto = test::with_model(big_rice(), Model::automatic);
        const BudgetChoice c = offered_level({full_auto}, f, f.cost.engine_step_s, false);
        CHECK(!c.reduced());  // nothing offered: nothing is stepped grain by grain
        CHECK(c.fits);
        CHECK(c.grains_asked == 0.0);
        CHECK(c.grains_on_hand_over == Approx(grains));
        CHECK_FALSE(c.fits_after_hand_over);
        const std::string said = budget_statement(c, c, f);
        CHECK_THAT(said, Catch::StartsWith("The scene as asked; it keeps real time on this computer."));
        CHECK_THAT(said, Catch::Contains(fmt::format("its grains (about {}) take over and play slower than real time",
                                                     std::lround(grains / 10.0) * 10)));
        CHECK_THAT(said, !Catch::Contains("costs more than real time"));
        // Beside a lane that does step its grains, only that lane's are counted and offered.
        // A quarter-filled hexagon: its grains (about 130) fit the budget on their own (about 250).
        const Scene quarter = test::with_model(
            test::scene_with({{"shell", "hexagon-small"}, {"fill", {{"ratio", 0.25}, {"material", "bb"}}}}),
            Model::automatic);
        const BudgetChoice race = offered_level({full_auto, quarter}, f, f.cost.engine_step_s, false);
        CHECK(!race.reduced());
        CHECK(race.grains_asked == Approx(0.9 * estimated_grain_count(quarter)));
        CHECK(race.grains_on_hand_over == Approx(grains));
    }
    SECTION("a machine fast enough keeps the big scene as asked") {
        // 0.7 s of physics per simulated second buys 0.7 / 1e-7 grain steps: 7,000 grains at 1,000 steps/s.
        const BudgetFigures f = figures(1e-7);
        const BudgetChoice c = offered_level(big, f, f.cost.engine_step_s, false);
        CHECK(!c.reduced());
        CHECK(c.fits);
    }
    SECTION("slightly too slow: grains 1.5x larger, the nearest level, is enough") {
        // Between the cost of the grains as asked and 1 / 1.5^2 of it.
        const double cost = 0.7 / (grains * 1000.0) * 1.5;
        const BudgetFigures f = figures(cost);
        const BudgetChoice c = offered_level(big, f, cost, false);
        REQUIRE(c.reduced());
        CHECK(f.levels.at(static_cast<size_t>(c.level)).grain_scale == 1.5);
        CHECK(f.levels.at(static_cast<size_t>(c.level)).fidelity.empty());
        CHECK(c.fits);
        CHECK(c.cost_asked > f.physics_share);
        CHECK(c.cost_chosen <= f.physics_share);
        CHECK(c.grains_chosen == Approx(c.grains_asked / 2.25).epsilon(0.01));
    }
    SECTION("much too slow: coarser grains first, then a coarser step") {
        const double cost = 0.7 / (grains * 1000.0) * 6.0;  // 2x grains alone (1/4) is not enough
        const BudgetFigures f = figures(cost);
        const BudgetChoice c = offered_level(big, f, cost, true);
        REQUIRE(c.reduced());
        const BudgetLevel& l = f.levels.at(static_cast<size_t>(c.level));
        CHECK(l.grain_scale == 2.0);
        CHECK(l.fidelity == "draft");
        CHECK(c.fits);
        CHECK(c.measured);
        const Scene chosen = apply_choice(big, f, c)[0];
        CHECK(chosen.fill.material.diameter_m == Approx(2.0 * big[0].fill.material.diameter_m));
        CHECK(chosen.fidelity.preset == "draft");
        CHECK(chosen.fill.ratio == big[0].fill.ratio);
        CHECK(chosen.fill.material.bulk_density_kg_m3 == big[0].fill.material.bulk_density_kg_m3);
    }
    SECTION("beyond every level: the cheapest, saying it still does not keep up") {
        const BudgetFigures f = figures(1e-3);
        const BudgetChoice c = offered_level(big, f, f.cost.engine_step_s, false);
        CHECK(c.level == static_cast<int>(f.levels.size()) - 1);
        CHECK(!c.fits);
        const BudgetChoice asked = picked_level(big, f, -1, f.cost.engine_step_s, false);
        CHECK_THAT(budget_statement(asked, c, f), Catch::Contains("comes closer to real time"));
    }
    SECTION("the scene as asked stays as asked however slow, saying it plays slower") {
        const BudgetFigures f = figures(1e-3);
        const BudgetChoice c = picked_level(big, f, -1, f.cost.engine_step_s, false);
        CHECK(!c.reduced());
        CHECK(!c.fits);
        CHECK(apply_choice(big, f, c)[0].fill.material.diameter_m == big[0].fill.material.diameter_m);
        const BudgetChoice offer = offered_level(big, f, f.cost.engine_step_s, false);
        CHECK_THAT(budget_statement(c, offer, f),
                   Catch::Contains("costs more than real time") && Catch::Contains("never differently"));
    }
    SECTION("a level is only ever the one picked, and its key names it on the command line") {
        const BudgetFigures f = figures(1e-9);  // a fast machine: the scene fits as asked
        const BudgetChoice c = picked_level(big, f, 1, f.cost.engine_step_s, false);
        CHECK(c.level == 1);
        CHECK(apply_choice(big, f, c)[0].fill.material.diameter_m ==
              Approx(f.levels[1].grain_scale * big[0].fill.material.diameter_m));
        CHECK(level_from_key("none", f) == -1);
        for (size_t i = 0; i < f.levels.size(); ++i) CHECK(level_from_key(level_key(f.levels[i]), f) == static_cast<int>(i));
        CHECK(level_key(f.levels.back()) == "2x-draft");
        CHECK_THROWS_WITH(level_from_key("3x", f), Catch::Contains("--coarser 3x") && Catch::Contains("allowed: none, 1.5x"));
        CHECK_THROWS(picked_level(big, f, 99, f.cost.engine_step_s, false));
    }
}

TEST_CASE("coarser grains keep the fill's mass and level in fewer grains", "[app][budget][fill]") {
    for (const char* material : {"bb", "rice", "peas"}) {
        for (double r : {0.25, 0.5, 1.0}) {
            const Scene s = test::scene_with({{"shell", "hexagon-large"}, {"fill", {{"ratio", r}, {"material", material}}}});
            const FillPlan fine = plan_fill(s, shell_properties(s.shell), {0.0, 1.0});
            for (double k : {1.5, 2.0}) {
                const Scene c = with_coarser_grains(s, k);
                INFO(material << ", r = " << r << ", grains " << k << "x larger");
                CHECK(disc_diameter_m(c) == Approx(k * disc_diameter_m(s)));
                CHECK(fill_mass_kg(c) == Approx(fill_mass_kg(s)).epsilon(1e-9));
                const FillPlan coarse = plan_fill(c, shell_properties(c.shell), {0.0, 1.0});
                CHECK(coarse.surface_level_m == Approx(fine.surface_level_m));
                CHECK(coarse.grains.size() < fine.grains.size());
            }
        }
    }
    CHECK_THROWS_WITH(with_coarser_grains(big_rice(), 0.5), Catch::Contains("0.5") && Catch::Contains("allowed"));
}

TEST_CASE("the panel names what the budget offers and what it costs", "[app][budget]") {
    const BudgetFigures f = figures(0.7 / (900 * 1000.0) * 6.0);
    const BudgetChoice c = offered_level({big_rice()}, f, f.cost.engine_step_s, false);
    REQUIRE(c.reduced());
    const BudgetLevel& l = f.levels.at(static_cast<size_t>(c.level));
    const BudgetChoice asked = picked_level({big_rice()}, f, -1, f.cost.engine_step_s, false);
    const std::string said = budget_statement(asked, c, f);
    CHECK_THAT(said, Catch::Contains("Offered: " + level_label(l)) && Catch::Contains("keeps real time") &&
                         Catch::Contains("same fill mass") && Catch::Contains("trade study"));
    // Picked, the same level says it was picked and what it costs.
    const BudgetChoice picked = picked_level({big_rice()}, f, c.level, f.cost.engine_step_s, false);
    CHECK_THAT(budget_statement(picked, c, f), Catch::Contains("as picked") && Catch::Contains(level_label(l)) &&
                                                   Catch::Contains(fmt::format("{:.1f}%", 100 * l.terminal_velocity_error)));
    // The level's measured error, as a percentage, and the full detail's beside it.
    CHECK_THAT(said, Catch::Contains(fmt::format("{:.1f}%", 100 * l.terminal_velocity_error)));
    CHECK_THAT(said, Catch::Contains(fmt::format("{:.1f}%", 100 * f.full_detail.terminal_velocity_error)));
    // From the lane's model and auto's choice, never from the label's text.
    const Scene grains = test::with_model(big_rice(), Model::grains);
    CHECK(budget_model_label(grains, nullptr, l) == level_label(l));
    ModelChoice filled;
    filled.model = Model::grains;
    CHECK(budget_model_label(grains, &filled, l) == "auto: " + level_label(l));
    ModelChoice handed;
    handed.model = Model::rigid;
    handed.then = Model::grains;
    handed.lift_off_time_s = 0.3;
    handed.hand_over_time_s = 0.412;
    CHECK(budget_model_label(grains, &handed, l) == "auto: grains from 0.41 s, " + level_label(l));
    CHECK_THAT(budget_status(l), Catch::Contains(level_label(l)) && Catch::Contains("picked in the panel"));
    CHECK(level_label({2.0, "draft", 0, 0, 0, ""}) == "grains 2x larger, draft step");
    CHECK(level_label({1.5, "", 0, 0, 0, ""}) == "grains 1.5x larger");
    // A pile costs more per grain than loose grains: the cost units grow faster than the grains, and
    // with the solver's iterations.
    const FidelityParams standard{"standard", 1000.0, 1, 12, 3};
    RunCostFigures linear = f.cost;
    linear.engine_exponent = 1.0;
    linear.engine_reference_iterations = 15.0;
    RunCostFigures pile = linear;
    pile.engine_exponent = 1.46;
    CHECK(engine_step_units(0, standard, pile) == Approx(1.0));
    CHECK(engine_step_units(1008, standard, linear) == Approx(1009.0));
    CHECK(engine_step_units(1008, standard, pile) / engine_step_units(251, standard, pile) ==
          Approx(std::pow(1009.0 / 252.0, 1.46)));
    const FidelityParams more_iterations{"", 1000.0, 1, 24, 6};
    CHECK(engine_step_units(1008, more_iterations, pile) == Approx(2.0 * engine_step_units(1008, standard, pile)));
    const BudgetChoice fast = picked_level({big_rice()}, figures(1e-9), -1, 1e-9, false);
    CHECK_THAT(budget_statement(fast, fast, f), Catch::Contains("as asked") && Catch::Contains("keeps real time"));
}

TEST_CASE("the sandbox's physics builds the model picked and never another", "[app][budget][physics]") {
    // The large hexagon 0.6 full of rice: more than the asset's measured machine can step at real time,
    // yet quicker to build than full.
    const Scene asked = test::scene_with({{"shell", "hexagon-large"}, {"fill", {{"ratio", 0.6}, {"material", "rice"}}}});
    const BudgetFigures& f = budget_figures();
    REQUIRE(estimated_cost_s({asked}, f.cost.engine_step_s, f) > f.physics_share);
    SandboxPhysics physics(true, [] { return 0.0; });  // a capture: the asset's cost, no measuring
    auto build = [&](int level) {
        PhysicsRequests r;
        r.model_level = level;
        r.restart_with = std::vector<Scene>{asked};
        r.wait_until_built = true;
        const PhysicsOutcome out = physics.run(r);
        REQUIRE(out.built);
        return physics.lanes().lane(0).grains();
    };
    // Too slow here, yet stepped as asked: the cheaper model is only offered.
    const int full = build(-1);
    CHECK(!physics.budget_choice().reduced());
    CHECK(!physics.budget_choice().fits);
    CHECK(physics.budget_offer().reduced());
    CHECK(physics.lanes().lane(0).scene().fill.material.diameter_m == asked.fill.material.diameter_m);
    CHECK(physics.lanes().lane(0).scene().fidelity.preset == asked.fidelity.preset);
    // Picked, it is stepped.
    const int reduced = build(physics.budget_offer().level);
    REQUIRE(physics.budget_choice().reduced());
    CHECK(physics.lanes().lane(0).scene().fill.material.diameter_m > asked.fill.material.diameter_m);
    CHECK(full > reduced);
    // And back to the scene as asked.
    CHECK(build(-1) == full);
}

// A slow machine: every call of the wall clock takes 4 ms, so a frame's 14 ms physics budget runs out
// after a few steps. The run must stay the scene as asked (same grains, same size, same step) and play
// slower instead, saying so; the cost it measured changes only the offer.
TEST_CASE("a slow measured cost slows the playback and never changes the scene stepped", "[app][budget][physics]") {
    const Scene asked = test::scene_with({{"shell", "hexagon-large"}, {"fill", {{"ratio", 0.6}, {"material", "rice"}}}});
    double fake_now = 0.0;
    SandboxPhysics physics(false, [&fake_now] { return fake_now += 0.004; });
    PhysicsRequests build;
    build.restart_with = std::vector<Scene>{asked};
    build.wait_until_built = true;
    build.play = true;
    REQUIRE(physics.run(build).built);
    const int grains = physics.lanes().lane(0).grains();
    REQUIRE(grains > 200);
    double simulated = 0.0;
    for (int frame = 0; frame < 150; ++frame) {  // 2.5 s of wall time at 60 frames/s
        PhysicsRequests r;
        r.frame = PhysicsRequests::Frame{1.0 / 60.0, 1};
        const PhysicsOutcome out = physics.run(r);
        CHECK(!out.built);  // never rebuilt
        simulated = out.time_s;
    }
    // The cost this window measured is far above the asset's: the offer is a cheaper level...
    CHECK(physics.measured_s_per_cost_unit() > budget_figures().cost.engine_step_s);
    CHECK(physics.budget_offer().reduced());
    CHECK(physics.budget_offer().measured);
    // ... but the lane is the scene as asked, from t = 0 on, played slower than real time.
    CHECK(!physics.budget_choice().reduced());
    const Scene& stepped = physics.lanes().lane(0).scene();
    CHECK(stepped.fill.material.diameter_m == asked.fill.material.diameter_m);
    CHECK(stepped.fidelity.preset == asked.fidelity.preset);
    CHECK(stepped.fidelity.step_hz == asked.fidelity.step_hz);
    CHECK(physics.lanes().lane(0).grains() == grains);
    CHECK(simulated < 0.5 * 2.5);
    CHECK(physics.clock().realtime_ratio() < 0.5);
    CHECK(!physics.clock().keeping_up());
    CHECK_THAT(speed_statement(1, true, physics.clock().keeping_up(), physics.clock().realtime_ratio()),
               Catch::Contains("real time: this scene costs more than real time here"));
}
