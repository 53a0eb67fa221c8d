// Plane geometry for polyroll: see geometry.h.
#include "sim/geometry/geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace polyroll::geom {

double length(Vec2 a) { return std::hypot(a.x, a.y); }

Vec2 rotate(Vec2 a, double angle_rad) {
    const double c = std::cos(angle_rad), s = std::sin(angle_rad);
    return {c * a.x - s * a.y, s * a.x + c * a.y};
}

std::vector<Vec2> regular_polygon(int sides, double circumradius, double first_vertex_angle_rad) {
    std::vector<Vec2> v(static_cast<size_t>(sides));
    for (int i = 0; i < sides; ++i) {
        const double a = first_vertex_angle_rad + 2.0 * kPi * i / sides;
        v[static_cast<size_t>(i)] = {circumradius * std::cos(a), circumradius * std::sin(a)};
    }
    return v;
}

double regular_polygon_area(int sides, double circumradius) {
    return 0.5 * sides * circumradius * circumradius * std::sin(2.0 * kPi / sides);
}

double regular_polygon_apothem(int sides, double circumradius) {
    return circumradius * std::cos(kPi / sides);
}

double regular_polygon_side(int sides, double circumradius) {
    return 2.0 * circumradius * std::sin(kPi / sides);
}

double regular_polygon_polar_moment(int sides, double circumradius) {
    const double c = std::cos(kPi / sides);
    return regular_polygon_area(sides, circumradius) * circumradius * circumradius * (1.0 + 2.0 * c * c) / 6.0;
}

AreaProperties triangle_properties(Vec2 a, Vec2 b, Vec2 c) {
    AreaProperties p;
    p.centroid = {(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
    const Vec2 ab = b - a, ac = c - a;
    p.area = std::fabs(cross(ab, ac)) / 2.0;
    const double d = length(ab);
    if (d == 0.0 || p.area == 0.0) return p;
    // Brief: I_cm = area (D^2 + K^2 + H^2 - K D) / 18 with K, H the projection and height of C on AB.
    const double k = dot(ab, ac) / d;
    const double h = std::fabs(cross(ab, ac)) / d;
    p.polar_moment_cm = p.area * (d * d + k * k + h * h - k * d) / 18.0;
    return p;
}

AreaProperties polygon_properties(const std::vector<Vec2>& poly) {
    AreaProperties out;
    if (poly.size() < 3) return out;
    // Fan from vertex 0; signed areas make this right for any simple polygon.
    double area = 0.0, jx = 0.0, jy = 0.0, j_origin = 0.0;
    const Vec2 o = poly[0];
    for (size_t i = 1; i + 1 < poly.size(); ++i) {
        const Vec2 a = poly[i] - o, b = poly[i + 1] - o;
        const double c = cross(a, b);  // twice the signed area of (o, a, b)
        area += c / 2.0;
        jx += c * (a.x + b.x) / 6.0;
        jy += c * (a.y + b.y) / 6.0;
        // Second polar moment about o of the triangle (0, a, b): c/12 (|a|^2 + a.b + |b|^2).
        j_origin += c / 12.0 * (dot(a, a) + dot(a, b) + dot(b, b));
    }
    if (area == 0.0) return out;
    const Vec2 centroid_rel = {jx / area, jy / area};
    out.area = std::fabs(area);
    out.centroid = o + centroid_rel;
    out.polar_moment_cm = std::fabs(j_origin - area * dot(centroid_rel, centroid_rel));
    return out;
}

std::vector<Vec2> clip_half_plane(const std::vector<Vec2>& poly, Vec2 normal, double offset) {
    std::vector<Vec2> out;
    const size_t n = poly.size();
    out.reserve(n + 2);
    for (size_t i = 0; i < n; ++i) {
        const Vec2 p = poly[i], q = poly[(i + 1) % n];
        const double dp = dot(p, normal) - offset, dq = dot(q, normal) - offset;
        if (dp <= 0.0) out.push_back(p);
        if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) {
            const double t = dp / (dp - dq);
            out.push_back(p + t * (q - p));
        }
    }
    return out;
}

double level_for_area_fraction(const std::vector<Vec2>& poly, Vec2 up, double fraction) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Vec2& p : poly) {
        lo = std::min(lo, dot(p, up));
        hi = std::max(hi, dot(p, up));
    }
    if (fraction <= 0.0) return lo;
    if (fraction >= 1.0) return hi;
    const double total = polygon_properties(poly).area;
    const double target = fraction * total;
    double a = lo, b = hi;
    for (int it = 0; it < 200 && b - a > 1e-14 * (hi - lo); ++it) {
        const double mid = 0.5 * (a + b);
        const double area = polygon_properties(clip_half_plane(poly, up, mid)).area;
        (area < target ? a : b) = mid;
    }
    return 0.5 * (a + b);
}

double inside_distance(const std::vector<Vec2>& ccw_poly, Vec2 p) {
    double d = std::numeric_limits<double>::infinity();
    const size_t n = ccw_poly.size();
    for (size_t i = 0; i < n; ++i) {
        const Vec2 a = ccw_poly[i], b = ccw_poly[(i + 1) % n];
        const Vec2 e = b - a;
        // Inward normal of a CCW edge is the edge rotated +90 degrees.
        const double dist = cross(e, p - a) / length(e);
        d = std::min(d, dist);
    }
    return d;
}

}  // namespace polyroll::geom
