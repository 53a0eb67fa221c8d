// The grain engine stepped in the pile's frame (sim/grains/moving_frame.h): the same motion as in the
// ramp's frame up to rounding, the ramp put back exactly, nothing changed where there are no grains
// or nothing moves, and fewer of Box2D's contacts.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim/grains/moving_frame.h"
#include "sim/grains/simulation.h"
#include "sim/grains/world_builder.h"
#include "test_helpers.h"

using namespace polyroll;

namespace {

Scene in_frame(const char* frame, nlohmann::ordered_json overrides = nlohmann::ordered_json::object()) {
    overrides["fidelity"]["frame"] = frame;
    // Box2D's own contacts, whose count the frame changes (near contacts: test_near_pairs.cpp).
    overrides["fidelity"]["contacts"] = "boxes";
    overrides["run"]["model"] = "grains";
    return test::scene_with(overrides);
}

long contacts_of(const SimWorld& w) {
    long n = 0;
    for (const b2Contact* c = w.world->GetContactList(); c != nullptr; c = c->GetNext()) ++n;
    return n;
}

}  // namespace

TEST_CASE("pile frame: the first steps match the ramp's frame to rounding, and the ramp stays at the origin",
          "[frame]") {
    auto ramp = build_world(in_frame("ramp"));
    auto pile = build_world(in_frame("pile"));
    REQUIRE(ramp->grains.size() == pile->grains.size());
    REQUIRE(ramp->ramp->GetType() == b2_staticBody);
    REQUIRE(pile->ramp->GetType() == b2_kinematicBody);
    // Built the same way, the two worlds start bit for bit alike.
    REQUIRE(ramp->shell->GetPosition().x == pile->shell->GetPosition().x);
    bool frame_moved = false;
    // 0.2 s after the release: the shell tips over its vertex and falls onto its first face, the
    // pile sliding inside, before the pile's chaos turns rounding into visible differences.
    for (int i = 0; i < 200; ++i) {
        frame_moved = frame_moved || frame_velocity_units(*pile) != 0.0f;
        ramp->step();
        pile->step();
        REQUIRE(pile->ramp->GetPosition().x == 0.0f);
        REQUIRE(pile->ramp->GetPosition().y == 0.0f);
        REQUIRE(pile->ramp->GetLinearVelocity().x == 0.0f);
    }
    CHECK(frame_moved);
    const double tol_m = 1e-4;
    CHECK(pile->units.to_m(pile->shell->GetPosition().x) ==
          Approx(ramp->units.to_m(ramp->shell->GetPosition().x)).margin(tol_m));
    CHECK(pile->units.to_m(pile->shell->GetPosition().y) ==
          Approx(ramp->units.to_m(ramp->shell->GetPosition().y)).margin(tol_m));
    CHECK(pile->shell->GetAngle() == Approx(ramp->shell->GetAngle()).margin(1e-3));
    CHECK(pile->shell->GetLinearVelocity().x == Approx(ramp->shell->GetLinearVelocity().x).margin(0.1));
    // The shell has moved well past those margins, so the check means something.
    CHECK(std::abs(ramp->units.to_m(ramp->shell->GetPosition().x) - ramp->start_centre_x_m) > 10 * tol_m);
}

TEST_CASE("pile frame: an empty shell runs bit for bit as in the ramp's frame", "[frame]") {
    const nlohmann::ordered_json empty = {{"fill", {{"ratio", 0.0}}}};
    Simulation a(in_frame("ramp", empty)), b(in_frame("pile", empty));
    while (a.step()) {
    }
    while (b.step()) {
    }
    const Measurements &ma = a.measured(), &mb = b.measured();
    CHECK(ma.behaviour == mb.behaviour);
    CHECK(ma.distance_m == mb.distance_m);
    CHECK(a.time_s() == b.time_s());
}

TEST_CASE("pile frame: a rolling pile keeps fewer contacts, and the run still rolls to the end", "[frame]") {
    // The default scene (the Fig. 7 hexagon, a quarter full, 20 deg) 1 s after the release.
    auto ramp = build_world(in_frame("ramp"));
    auto pile = build_world(in_frame("pile"));
    long contacts_ramp = 0, contacts_pile = 0;
    for (int i = 0; i < 1000; ++i) {
        ramp->step();
        pile->step();
        if (i >= 500 && i % 50 == 0) contacts_ramp += contacts_of(*ramp), contacts_pile += contacts_of(*pile);
    }
    CAPTURE(contacts_ramp, contacts_pile);
    CHECK(contacts_pile < contacts_ramp);

    Simulation run(in_frame("pile"));
    while (run.step()) {
    }
    CHECK(run.measured().behaviour == Behaviour::rolled_to_end);
}
