// The grain simulation (named: auto would run the rigid model itself) of an empty shell against the rigid impact model (docs/physics.md): each
// face impact should keep the share of kinetic energy the model predicts from the shell's mass,
// moment of inertia and pivot radius, wherever the model's assumption (no hopping) holds.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim/geometry/shell_properties.h"
#include "test_helpers.h"

using namespace polyroll;

namespace {

struct Check {
    double model_ratio = 0.0;
    double measured_ratio = 0.0;
    size_t impacts = 0;
    double faces_travelled = 0.0;
    double relative_error() const { return std::fabs(measured_ratio - model_ratio) / model_ratio; }
};

Check rolling_check(int sides, double angle_deg, const char* fidelity) {
    // The rigid model's vertices are sharp: the engine's shell as sharp as it makes one (its skin).
    const Scene s = test::scene_with({{"shell", {{"preset", "hexagon-small"}, {"sides", sides}, {"vertex_radius_m", 0.0}}},
                                      {"fill", {{"ratio", 0.0}}},
                                      {"ramp", {{"angle_deg", angle_deg}}},
                                      {"fidelity", fidelity},
                                      {"run", {{"model", "grains"}}}});
    const RunResult r = run_scene(s);
    Check c;
    c.model_ratio = rigid_impact_energy_ratio(sides, r.shell.mass_kg, r.shell.inertia_kg_m2, r.shell.pivot_radius_m);
    const auto& imp = r.measured.impacts;
    REQUIRE(r.measured.behaviour == Behaviour::rolled_to_end);
    // Steady rolling: skip the first impacts, where the release is still being forgotten.
    REQUIRE(imp.size() > 10);
    double sum = 0.0;
    for (size_t i = 3; i < imp.size(); ++i) sum += imp[i].ratio();
    c.measured_ratio = sum / static_cast<double>(imp.size() - 3);
    c.impacts = imp.size();
    c.faces_travelled = r.measured.distance_m / r.shell.outer_side_m;
    return c;
}

}  // namespace

TEST_CASE("empty shells lose the rigid model's share of energy per impact (n = 6, 8, 10 at 10 degrees)", "[physics][rigid]") {
    for (int n : {6, 8, 10}) {
        const Check standard = rolling_check(n, 10.0, "standard");
        const Check precise = rolling_check(n, 10.0, "precise");
        INFO("n = " << n << ": model Q = " << standard.model_ratio << ", standard " << standard.measured_ratio
                    << ", precise " << precise.measured_ratio);
        // The model holds only while the shell stays on the ramp: every face is landed, none skipped.
        CHECK(std::fabs(static_cast<double>(standard.impacts) - standard.faces_travelled) <= 1.5);
        CHECK(standard.relative_error() < 0.03);
        // Closer at the precise preset: a third of the standard tolerance. (Measured: both presets
        // land within 0.2-0.7% of the model, where the one-step resolution of "just before" and
        // "just after" sets the floor, so precise is not reliably closer than standard beyond it.)
        CHECK(precise.relative_error() < 0.01);
    }
}

TEST_CASE("where the shell hops, the measured impacts leave the rigid model", "[physics][rigid]") {
    // n = 18 hops above about 8 degrees (docs/design.md): faces are skipped, energy is kept.
    const Check c = rolling_check(18, 10.0, "standard");
    INFO("impacts " << c.impacts << " over " << c.faces_travelled << " faces");
    CHECK(static_cast<double>(c.impacts) < c.faces_travelled - 3.0);
}
