// The sandbox's physics budget (issue 13 item 3): which model it steps when the scenes asked for cannot
// keep real time, that coarser grains keep the fill's mass, that full detail gives the scenes back as
// asked, and what the panel says. Figures are set here (not the asset's measured ones), so the choices
// do not depend on the machine the asset was measured on.
#include <catch2/catch.hpp>

#include <cmath>

#include <fmt/format.h>

#include "sim/disc_size.h"
#include "app/model_budget.h"
#include "app/readouts.h"
#include "app/sandbox_physics.h"
#include "sim/fill_plan.h"
#include "sim/scene_validate.h"
#include "test_helpers.h"

using namespace polyroll;
using namespace polyroll::app;
using json = nlohmann::ordered_json;

namespace {

// The asset's levels and errors, with a chosen cost and share.
BudgetFigures figures(double cost_per_grain_step) {
    BudgetFigures f = budget_figures();
    f.physics_s_per_grain_step = cost_per_grain_step;
    f.physics_share = 0.7;
    f.packing = 0.9;
    f.cost_exponent = 1.0;  // linear, so the thresholds below are plain sums
    return f;
}

Scene big_rice() {
    return test::scene_with({{"shell", "hexagon-large"}, {"fill", {{"ratio", 1.0}, {"material", "rice"}}}});
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
            const BudgetChoice c = choose_model({s}, f, f.physics_s_per_grain_step, false, false);
            CHECK(!c.reduced());
            CHECK(c.fits);
            CHECK(apply_choice({s}, f, c)[0].fill.material.diameter_m == s.fill.material.diameter_m);
        }
    }
    SECTION("a machine fast enough keeps the big scene as asked") {
        // 0.7 s of physics per simulated second buys 0.7 / 1e-7 grain steps: 7,000 grains at 1,000 steps/s.
        const BudgetFigures f = figures(1e-7);
        const BudgetChoice c = choose_model(big, f, f.physics_s_per_grain_step, false, false);
        CHECK(!c.reduced());
        CHECK(c.fits);
    }
    SECTION("slightly too slow: grains 1.5x larger, the nearest level, is enough") {
        // Between the cost of the grains as asked and 1 / 1.5^2 of it.
        const double cost = 0.7 / (grains * 1000.0) * 1.5;
        const BudgetFigures f = figures(cost);
        const BudgetChoice c = choose_model(big, f, cost, false, false);
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
        const BudgetChoice c = choose_model(big, f, cost, true, false);
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
        const BudgetChoice c = choose_model(big, f, f.physics_s_per_grain_step, false, false);
        CHECK(c.level == static_cast<int>(f.levels.size()) - 1);
        CHECK(!c.fits);
        CHECK_THAT(budget_statement(c, f), Catch::Contains("still slower"));
    }
    SECTION("full detail keeps the scene as asked however slow") {
        const BudgetFigures f = figures(1e-3);
        const BudgetChoice c = choose_model(big, f, f.physics_s_per_grain_step, false, true);
        CHECK(!c.reduced());
        CHECK(!c.fits);
        CHECK(apply_choice(big, f, c)[0].fill.material.diameter_m == big[0].fill.material.diameter_m);
        CHECK_THAT(budget_statement(c, f), Catch::Contains("Full detail") && Catch::Contains("slower than real time"));
    }
}

TEST_CASE("coarser grains keep the fill's mass and level in fewer grains", "[app][budget][fill]") {
    for (const char* material : {"bb", "rice", "peas"}) {
        for (double r : {0.25, 0.5, 1.0}) {
            const Scene s = test::scene_with({{"shell", "hexagon-large"}, {"fill", {{"ratio", r}, {"material", material}}}});
            for (double k : {1.5, 2.0}) {
                const Scene c = with_coarser_grains(s, k);
                INFO(material << ", r = " << r << ", grains " << k << "x larger");
                CHECK(disc_diameter_m(c) == Approx(k * disc_diameter_m(s)));
                CHECK(fill_mass_kg(c) == Approx(fill_mass_kg(s)).epsilon(1e-9));
                const FillPlan fine = plan_fill(s, shell_properties(s.shell), {0.0, 1.0});
                const FillPlan coarse = plan_fill(c, shell_properties(c.shell), {0.0, 1.0});
                CHECK(coarse.surface_level_m == Approx(fine.surface_level_m));
                CHECK(coarse.grains.size() < fine.grains.size());
            }
        }
    }
    CHECK_THROWS_WITH(with_coarser_grains(big_rice(), 0.5), Catch::Contains("0.5") && Catch::Contains("allowed"));
}

TEST_CASE("the panel names what the budget chose and what it costs", "[app][budget]") {
    const BudgetFigures f = figures(0.7 / (900 * 1000.0) * 6.0);
    const BudgetChoice c = choose_model({big_rice()}, f, f.physics_s_per_grain_step, false, false);
    REQUIRE(c.reduced());
    const BudgetLevel& l = f.levels.at(static_cast<size_t>(c.level));
    const std::string said = budget_statement(c, f);
    CHECK_THAT(said, Catch::Contains("To keep real time") && Catch::Contains(level_label(l)) &&
                         Catch::Contains("same fill mass") && Catch::Contains("trade study"));
    // The level's measured error, as a percentage, and the full detail's beside it.
    CHECK_THAT(said, Catch::Contains(fmt::format("{:.1f}%", 100 * l.terminal_velocity_error)));
    CHECK_THAT(said, Catch::Contains(fmt::format("{:.1f}%", 100 * f.full_detail.terminal_velocity_error)));
    CHECK(budget_model_label("grains", l) == level_label(l));
    CHECK(budget_model_label("auto: grains", l) == "auto: " + level_label(l));
    CHECK_THAT(budget_status(l), Catch::Contains(level_label(l)) && Catch::Contains("full detail"));
    CHECK(level_label({2.0, "draft", 0, 0, 0, ""}) == "grains 2x larger, draft step");
    CHECK(level_label({1.5, "", 0, 0, 0, ""}) == "grains 1.5x larger");
    // A pile costs more per grain than loose grains: the grain steps grow faster than the grains.
    CHECK(grain_steps_per_engine_step(0, 1.84) == Approx(1.0));
    CHECK(grain_steps_per_engine_step(1008, 1.0) == Approx(1009.0));
    CHECK(grain_steps_per_engine_step(1008, 1.84) / grain_steps_per_engine_step(251, 1.84) ==
          Approx(std::pow(1009.0 / 252.0, 1.84)));
    CHECK_THAT(budget_statement(choose_model({big_rice()}, figures(1e-9), 1e-9, false, false), f),
               Catch::Contains("as asked"));
}

TEST_CASE("the sandbox's physics builds the budget's choice, and full detail restores the scene as asked",
          "[app][budget][physics]") {
    // The large hexagon 0.6 full of rice: more than the asset's measured machine can step at real time,
    // yet quicker to build than full.
    const Scene asked = test::scene_with({{"shell", "hexagon-large"}, {"fill", {{"ratio", 0.6}, {"material", "rice"}}}});
    const BudgetFigures& f = budget_figures();
    REQUIRE(estimated_cost_s({asked}, f.physics_s_per_grain_step, f) > f.physics_share);
    SandboxPhysics physics(true, [] { return 0.0; });  // a capture: the asset's cost, no measuring
    auto build = [&](bool full_detail) {
        PhysicsRequests r;
        r.full_detail = full_detail;
        r.restart_with = std::vector<Scene>{asked};
        r.wait_until_built = true;
        const PhysicsOutcome out = physics.run(r);
        REQUIRE(out.built);
        return physics.lanes().lane(0).grains();
    };
    const int reduced = build(false);
    REQUIRE(physics.budget_choice().reduced());
    CHECK(physics.lanes().lane(0).scene().fill.material.diameter_m > asked.fill.material.diameter_m);
    const int full = build(true);
    CHECK(!physics.budget_choice().reduced());
    CHECK(physics.budget_choice().full_detail_asked);
    CHECK(physics.lanes().lane(0).scene().fill.material.diameter_m == asked.fill.material.diameter_m);
    CHECK(physics.lanes().lane(0).scene().fidelity.preset == asked.fidelity.preset);
    CHECK(full > reduced);
    // And back: the budget's choice again.
    CHECK(build(false) == reduced);
}
