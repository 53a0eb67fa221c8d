// The shell's derived properties (mass split, moment of inertia of the 3D box, pivot radius) and the
// rigid impact model's energy ratio, against closed forms and an independent computation.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim/geometry/geometry.h"
#include "sim/geometry/shell_outline.h"
#include "sim/geometry/shell_properties.h"
#include "sim/geometry/vertex_rounding.h"

using namespace polyroll;

namespace {
ShellParams small_hexagon() {
    ShellParams s;
    s.sides = 6;
    s.inner_circumradius_m = 0.0336;
    s.wall_thickness_m = 0.002;
    s.depth_m = 0.062;
    s.lid_thickness_m = 0.001;
    s.mass_kg = 0.033;
    return s;
}
}  // namespace

TEST_CASE("outer geometry follows from the wall thickness measured across each face", "[shell]") {
    const ShellProperties p = shell_properties(small_hexagon());
    CHECK(p.inner_apothem_m == Approx(0.0336 * std::cos(geom::kPi / 6)));
    CHECK(p.outer_apothem_m - p.inner_apothem_m == Approx(0.002));
    CHECK(p.outer_circumradius_m == Approx(p.outer_apothem_m / std::cos(geom::kPi / 6)));
    CHECK(p.pivot_radius_m == p.outer_circumradius_m);
    CHECK(p.outer_side_m == Approx(p.outer_circumradius_m));  // a hexagon's side equals its circumradius
    CHECK(p.inside_volume_m3 == Approx(1.5 * std::sqrt(3.0) * 0.0336 * 0.0336 * 0.062));
}

TEST_CASE("shell inertia: walls as a sum of trapezoids, lids as plates", "[shell]") {
    for (int n : {3, 6, 8, 10, 18, 64}) {
        ShellParams s = small_hexagon();
        s.sides = n;
        s.lid_mass_fraction = 0.3;
        const ShellProperties p = shell_properties(s);
        // Independent path: each wall trapezoid's own moment about its centroid, moved to the centre
        // with the parallel-axis theorem, mass shared by area.
        const auto inner = geom::regular_polygon(n, s.inner_circumradius_m);
        const auto outer = geom::regular_polygon(n, p.outer_circumradius_m);
        double wall_area = 0, wall_j = 0;
        for (int i = 0; i < n; ++i) {
            const int j = (i + 1) % n;
            const auto t = geom::polygon_properties({inner[i], outer[i], outer[j], inner[j]});
            wall_area += t.area;
            wall_j += t.polar_moment_cm + t.area * geom::dot(t.centroid, t.centroid);
        }
        const double m_walls = 0.7 * s.mass_kg, m_lids = 0.3 * s.mass_kg;
        const double lid_j_per_area = geom::polygon_properties(outer).polar_moment_cm / geom::polygon_properties(outer).area;
        const double expected = m_walls * wall_j / wall_area + m_lids * lid_j_per_area;
        INFO("n = " << n);
        CHECK(p.inertia_kg_m2 == Approx(expected).epsilon(1e-10));
        CHECK(p.lid_inertia_share == Approx(m_lids * lid_j_per_area / expected).epsilon(1e-10));
    }
}

TEST_CASE("thin walls without lids approach a ring: I = M R^2 (1 + ...) near the pivot radius", "[shell]") {
    ShellParams s = small_hexagon();
    s.sides = 64;
    s.wall_thickness_m = 1e-6;
    s.lid_thickness_m = 0.0;
    const ShellProperties p = shell_properties(s);
    CHECK(p.lid_mass_fraction == 0.0);
    // A thin circular ring has I = M R^2.
    CHECK(p.inertia_kg_m2 == Approx(s.mass_kg * s.inner_circumradius_m * s.inner_circumradius_m).epsilon(2e-3));
}

TEST_CASE("mass splits by volume when the lids' share is not given", "[shell]") {
    const ShellProperties p = shell_properties(small_hexagon());
    CHECK(p.lid_mass_fraction == Approx(p.lid_volume_m3 / (p.lid_volume_m3 + p.wall_volume_m3)));
    CHECK(p.lid_mass_fraction > 0.15);
    CHECK(p.lid_mass_fraction < 0.3);
}

TEST_CASE("rigid impact ratio: the brief's solid square and hexagon", "[shell]") {
    // Uniform solid polygon: I0 = M R^2 (1 + 2 cos^2(pi/n)) / 6.
    auto solid = [](int n) {
        const double c = std::cos(geom::kPi / n);
        return rigid_impact_energy_ratio(n, 1.0, (1.0 + 2.0 * c * c) / 6.0, 1.0);
    };
    CHECK(solid(4) == Approx(0.0625).margin(5e-5));
    CHECK(solid(6) == Approx(0.4187).margin(5e-5));
    CHECK(solid(8) > solid(6));
    CHECK(solid(18) > solid(8));
}

TEST_CASE("rounded vertices: arcs tangent to both faces, no drop on a face, r (1/cos(pi/n) - 1) on a vertex",
          "[shell][vertex]") {
    for (int n : {3, 6, 8, 18}) {
        ShellParams s = small_hexagon();
        s.sides = n;
        s.vertex_radius_m = 0.001;
        const std::vector<geom::Vec2> outer = shell_outer_polygon_m(s);
        const std::vector<geom::Vec2> arcs = vertex_arc_centres_m(s);
        REQUIRE(arcs.size() == outer.size());
        const ShellProperties p = shell_properties(s);
        INFO("n = " << n);
        for (const geom::Vec2& c : arcs) {
            // Each arc's centre lies one radius inside both faces that meet at its vertex: an
            // apothem less the radius from the polygon's centre, measured along either face normal.
            CHECK(geom::length(c) == Approx(p.outer_circumradius_m - vertex_arc_inset_m(n, 0.001)));
            CHECK(geom::length(c) * std::cos(geom::kPi / n) == Approx(p.outer_apothem_m - 0.001));
        }
        // On face (0, 1), angle 0: the arcs touch the ramp where the face does.
        CHECK(vertex_rounding_drop_m(s, 0.0) == Approx(0.0).margin(1e-12));
        // Vertex 1 straight down (the centre above the pivot): the sharp vertex stands r (1/cos - 1) up.
        const double on_vertex = -geom::kPi / n;
        CHECK(vertex_rounding_drop_m(s, on_vertex) == Approx(0.001 / std::cos(geom::kPi / n) - 0.001));
        CHECK(vertex_rounding_drop_m(s, on_vertex) == Approx(vertex_rounding_lift_max_m(s)));
        // Anywhere between, no more than that.
        for (double a = 0.0; a > -2.0 * geom::kPi / n; a -= 0.01)
            CHECK(vertex_rounding_drop_m(s, a) <= vertex_rounding_lift_max_m(s) + 1e-12);
    }
}
