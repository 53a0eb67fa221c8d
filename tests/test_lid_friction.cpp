// The grains' friction on the lids (sim/grains/lid_friction.h): its load, and that it only ever takes
// energy out of the fill's sliding relative to the shell while conserving momentum.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim/grains/lid_friction.h"
#include "sim/grains/world_builder.h"
#include "test_helpers.h"

using namespace polyroll;

namespace {

struct Totals {
    double kinetic_j = 0.0;
    double momentum_x = 0.0, momentum_y = 0.0;  // kg m/s
};

Totals totals(const SimWorld& w) {
    Totals t;
    auto add = [&](const b2Body* b) {
        const b2Vec2 v = b->GetLinearVelocity();
        const double vx = w.units.to_m(v.x), vy = w.units.to_m(v.y);
        const double inertia_kg_m2 = b->GetInertia() / (w.units.units_per_m * w.units.units_per_m);
        const double omega = b->GetAngularVelocity();
        t.kinetic_j += 0.5 * b->GetMass() * (vx * vx + vy * vy) + 0.5 * inertia_kg_m2 * omega * omega;
        t.momentum_x += b->GetMass() * vx;
        t.momentum_y += b->GetMass() * vy;
    };
    add(w.shell);
    for (const b2Body* g : w.grains) add(g);
    return t;
}

b2Vec2 relative_velocity(const SimWorld& w, const b2Body* g) {
    const b2Vec2 r = g->GetPosition() - w.shell->GetWorldCenter();
    const float omega = w.shell->GetAngularVelocity();
    return g->GetLinearVelocity() - (w.shell->GetLinearVelocity() + b2Vec2(-omega * r.y, omega * r.x));
}

}  // namespace

TEST_CASE("lid load: Jaky's lateral ratio and the column's weight times 2 K h / depth", "[lid_friction]") {
    CHECK(lateral_pressure_ratio(0.0) == Approx(1.0));
    CHECK(lateral_pressure_ratio(0.5) == Approx(1.0 - std::sin(std::atan(0.5))));
    // A column 3.1 cm deep in a 6.2 cm box with K = 0.5: its weight on the lids.
    CHECK(lid_normal_force_n(0.002, 9.81, 0.031, 0.062, 0.5) == Approx(0.002 * 9.81 * 0.5));
    CHECK(lid_normal_force_n(0.002, 9.81, 0.0, 0.062, 0.5) == 0.0);
}

TEST_CASE("lid friction removes energy, keeps momentum and never reverses a grain's sliding", "[lid_friction]") {
    for (double lid_friction : {0.3, 2.0}) {
        CAPTURE(lid_friction);
        const Scene s = test::scene_with({{"fill", {{"material", {{"lid_friction", lid_friction}}}}}});
        auto w = build_world(s);
        REQUIRE(!w->grains.empty());
        // Set the shell turning and sliding and the grains moving every way, as after an impact.
        w->shell->SetLinearVelocity({30.0f, -5.0f});
        w->shell->SetAngularVelocity(-8.0f);
        for (std::size_t i = 0; i < w->grains.size(); ++i) {
            const float a = 0.7f * static_cast<float>(i);
            w->grains[i]->SetLinearVelocity({40.0f * std::cos(a), 40.0f * std::sin(a)});
        }
        std::vector<b2Vec2> before;
        for (const b2Body* g : w->grains) before.push_back(relative_velocity(*w, g));
        const Totals t0 = totals(*w);
        // A long step: the cap, not the kinetic friction, decides for many grains.
        apply_lid_friction(*w, 0.01);
        const Totals t1 = totals(*w);
        CHECK(t1.kinetic_j < t0.kinetic_j);
        CHECK(t1.momentum_x == Approx(t0.momentum_x).epsilon(1e-5));
        CHECK(t1.momentum_y == Approx(t0.momentum_y).epsilon(1e-5));
        for (std::size_t i = 0; i < w->grains.size(); ++i) {
            // The pair's impulse may stop the sliding but not turn it round.
            CHECK(b2Dot(before[i], relative_velocity(*w, w->grains[i])) >= -1e-3f * before[i].LengthSquared());
        }
    }
}

TEST_CASE("lid friction 0 adds no term, and with it the default scene still runs to an outcome", "[lid_friction]") {
    const Scene off = test::scene_with(nlohmann::ordered_json::object());
    CHECK(build_world(off)->force_hooks.empty());
    const Scene on = test::scene_with({{"fill", {{"material", {{"lid_friction", 0.3}}}}}, {"run", {{"time_limit_s", 3}}}});
    CHECK(build_world(on)->force_hooks.size() == 1);
    const RunResult r = run_scene(on);
    CHECK(r.measured.behaviour != Behaviour::diverged);
    CHECK(r.measured.behaviour != Behaviour::running);
}
