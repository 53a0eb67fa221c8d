// Geometry: areas, centroids and polar moments of polygons and triangles against closed forms and
// against independent computations.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim/geometry/geometry.h"

using namespace polyroll::geom;

TEST_CASE("regular polygon area and polar moment match closed forms", "[geometry]") {
    // Square of side a: area a^2, polar moment a^4 / 6 (textbook), circumradius a / sqrt 2.
    const double a = 0.3;
    CHECK(regular_polygon_area(4, a / std::sqrt(2.0)) == Approx(a * a).epsilon(1e-12));
    CHECK(regular_polygon_polar_moment(4, a / std::sqrt(2.0)) == Approx(std::pow(a, 4) / 6.0).epsilon(1e-12));
    // Equilateral triangle of side s: area sqrt(3)/4 s^2, polar moment sqrt(3)/48 s^4.
    const double s = 0.7;
    const double r3 = s / std::sqrt(3.0);
    CHECK(regular_polygon_area(3, r3) == Approx(std::sqrt(3.0) / 4.0 * s * s).epsilon(1e-12));
    CHECK(regular_polygon_polar_moment(3, r3) == Approx(std::sqrt(3.0) / 48.0 * std::pow(s, 4)).epsilon(1e-12));
    // Hexagon of side s (= circumradius): area 3 sqrt(3)/2 s^2, polar moment 5 sqrt(3)/8 s^4.
    CHECK(regular_polygon_area(6, s) == Approx(1.5 * std::sqrt(3.0) * s * s).epsilon(1e-12));
    CHECK(regular_polygon_polar_moment(6, s) == Approx(5.0 * std::sqrt(3.0) / 8.0 * std::pow(s, 4)).epsilon(1e-12));
    // Many sides approach the disc: pi R^2 and pi R^4 / 2.
    CHECK(regular_polygon_area(64, 1.0) == Approx(kPi).epsilon(2e-3));
    CHECK(regular_polygon_polar_moment(64, 1.0) == Approx(kPi / 2.0).epsilon(4e-3));
    CHECK(regular_polygon_apothem(6, 2.0) == Approx(std::sqrt(3.0)));
    CHECK(regular_polygon_side(6, 2.0) == Approx(2.0));
}

TEST_CASE("polygon properties from vertices agree with the closed forms for n = 3..64", "[geometry]") {
    for (int n = 3; n <= 64; ++n) {
        const double R = 0.05 + 0.001 * n;
        const auto poly = regular_polygon(n, R, 0.37);
        const AreaProperties p = polygon_properties(poly);
        INFO("n = " << n);
        CHECK(p.area == Approx(regular_polygon_area(n, R)).epsilon(1e-12));
        CHECK(p.centroid.x == Approx(0.0).margin(1e-14));
        CHECK(p.centroid.y == Approx(0.0).margin(1e-14));
        CHECK(p.polar_moment_cm == Approx(regular_polygon_polar_moment(n, R)).epsilon(1e-11));
    }
}

TEST_CASE("a shifted polygon keeps its area and moment about its centroid", "[geometry]") {
    auto poly = regular_polygon(7, 1.0);
    const AreaProperties centred = polygon_properties(poly);
    for (auto& v : poly) v = v + Vec2{3.0, -2.0};
    const AreaProperties shifted = polygon_properties(poly);
    CHECK(shifted.area == Approx(centred.area));
    CHECK(shifted.centroid.x == Approx(3.0));
    CHECK(shifted.centroid.y == Approx(-2.0));
    CHECK(shifted.polar_moment_cm == Approx(centred.polar_moment_cm).epsilon(1e-10));
}

TEST_CASE("triangle properties (brief's formulas) agree with the side-length form and with the fan", "[geometry]") {
    const Vec2 tris[][3] = {{{0, 0}, {1, 0}, {0, 1}},
                            {{0.2, -0.1}, {1.7, 0.4}, {0.5, 2.3}},
                            {{-1, -1}, {3, -0.5}, {2.9, -0.2}},  // thin and obtuse
                            {{0, 0}, {0, 1}, {1, 0}}};          // clockwise
    for (const auto& t : tris) {
        const AreaProperties p = triangle_properties(t[0], t[1], t[2]);
        const double a = length(t[1] - t[2]), b = length(t[0] - t[2]), c = length(t[0] - t[1]);
        // Heron's formula for the area; mass (a^2 + b^2 + c^2) / 36 for the moment.
        const double sp = (a + b + c) / 2;
        const double heron = std::sqrt(sp * (sp - a) * (sp - b) * (sp - c));
        CHECK(p.area == Approx(heron).epsilon(1e-10));
        CHECK(p.polar_moment_cm == Approx(heron * (a * a + b * b + c * c) / 36.0).epsilon(1e-10));
        const AreaProperties fan = polygon_properties({t[0], t[1], t[2]});
        CHECK(p.polar_moment_cm == Approx(fan.polar_moment_cm).epsilon(1e-10));
        CHECK(p.centroid.x == Approx(fan.centroid.x));
        CHECK(p.centroid.y == Approx(fan.centroid.y));
    }
}

TEST_CASE("clipping below a level line gives the requested area fraction", "[geometry]") {
    for (int n : {3, 4, 6, 8, 18, 64}) {
        const auto poly = regular_polygon(n, 1.0, -kPi / 2 - kPi / n);
        for (double angle : {0.0, 0.3, 1.1}) {
            const Vec2 up = {-std::sin(angle), std::cos(angle)};
            for (double r : {0.0, 0.01, 0.125, 0.5, 0.74, 0.99, 1.0}) {
                const double h = level_for_area_fraction(poly, up, r);
                const double area = polygon_properties(clip_half_plane(poly, up, h)).area;
                INFO("n = " << n << ", tilt " << angle << ", r = " << r);
                CHECK(area / regular_polygon_area(n, 1.0) == Approx(r).margin(1e-9));
            }
        }
    }
}

TEST_CASE("inside distance is the distance to the nearest edge, negative outside", "[geometry]") {
    const auto square = regular_polygon(4, std::sqrt(2.0), kPi / 4);  // the square [-1, 1]^2
    CHECK(inside_distance(square, {0, 0}) == Approx(1.0));
    CHECK(inside_distance(square, {0.5, 0.2}) == Approx(0.5));
    CHECK(inside_distance(square, {1.5, 0}) == Approx(-0.5));
}
