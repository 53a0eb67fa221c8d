// Plane geometry in doubles: regular polygons, triangles, polygon mass properties and clipping.
// Pure math with no engine types, shared by the Box2D builder, the reduced models and the tests.
#pragma once

#include <vector>

namespace polyroll::geom {

struct Vec2 {
    double x = 0.0;
    double y = 0.0;
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
double length(Vec2 a);
Vec2 rotate(Vec2 a, double angle_rad);

inline constexpr double kPi = 3.14159265358979323846;

// Vertices of a regular n-gon (counter-clockwise) with circumradius R about the origin; vertex 0 at
// angle `first_vertex_angle_rad` from the +x axis.
std::vector<Vec2> regular_polygon(int sides, double circumradius, double first_vertex_angle_rad = 0.0);

// Closed forms for a regular n-gon of circumradius R.
double regular_polygon_area(int sides, double circumradius);
double regular_polygon_apothem(int sides, double circumradius);
double regular_polygon_side(int sides, double circumradius);
// Polar second moment of area about the centre (m^4 for R in m): area * R^2 (1 + 2 cos^2(pi/n)) / 6.
double regular_polygon_polar_moment(int sides, double circumradius);

// Mass properties of a simple polygon (any orientation) per unit areal density.
struct AreaProperties {
    double area = 0.0;           // always >= 0
    Vec2 centroid;
    double polar_moment_cm = 0.0;  // second polar moment of area about the centroid
};
AreaProperties polygon_properties(const std::vector<Vec2>& poly);

// Triangle properties from vertex coordinates: the formulas in docs/physics.md ("Triangle properties
// from corner coordinates").
AreaProperties triangle_properties(Vec2 a, Vec2 b, Vec2 c);

// The part of a convex polygon on the side of the line where dot(p, normal) <= offset.
std::vector<Vec2> clip_half_plane(const std::vector<Vec2>& poly, Vec2 normal, double offset);

// The offset h such that the part of convex `poly` with dot(p, up) <= h has area fraction `fraction`
// (0..1) of the whole; `up` is a unit vector. Bisection to ~1e-13 of the polygon's extent.
double level_for_area_fraction(const std::vector<Vec2>& poly, Vec2 up, double fraction);

// Signed distance from p to the boundary of a convex counter-clockwise polygon: positive inside.
double inside_distance(const std::vector<Vec2>& ccw_poly, Vec2 p);

}  // namespace polyroll::geom
