// Mass properties, the fill level and the fill's triangular segments: see composite_body.h.
#include "sim/reduced/composite_body.h"

#include <algorithm>
#include <cmath>

namespace polyroll::models {

using geom::Vec2;

MassProperties combine(const MassProperties& a, const MassProperties& b) {
    MassProperties c;
    c.mass_kg = a.mass_kg + b.mass_kg;
    if (c.mass_kg <= 0.0) return c;
    c.centre_of_mass_m = (1.0 / c.mass_kg) * (a.mass_kg * a.centre_of_mass_m + b.mass_kg * b.centre_of_mass_m);
    c.inertia_cm_kg_m2 = inertia_about(a, c.centre_of_mass_m) + inertia_about(b, c.centre_of_mass_m);
    return c;
}

double inertia_about(const MassProperties& body, Vec2 point) {
    const Vec2 d = body.centre_of_mass_m - point;
    return body.inertia_cm_kg_m2 + body.mass_kg * geom::dot(d, d);
}

double area_below(const std::vector<Vec2>& poly, Vec2 up, double level) {
    // The shoelace sum over the clipped polygon's vertices as clip_half_plane would emit them.
    double twice = 0.0;
    bool started = false;
    Vec2 first, prev;
    auto emit = [&](Vec2 p) {
        if (started) twice += geom::cross(prev, p);
        else first = p;
        started = true;
        prev = p;
    };
    const size_t n = poly.size();
    for (size_t i = 0; i < n; ++i) {
        const Vec2 p = poly[i], q = poly[(i + 1) % n];
        const double dp = geom::dot(p, up) - level, dq = geom::dot(q, up) - level;
        if (dp <= 0.0) emit(p);
        if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) emit(p + (dp / (dp - dq)) * (q - p));
    }
    if (started) twice += geom::cross(prev, first);
    return 0.5 * std::fabs(twice);
}

double fill_level(const std::vector<Vec2>& poly, Vec2 up, double fraction) {
    std::vector<double> heights;
    heights.reserve(poly.size());
    for (const Vec2& p : poly) heights.push_back(geom::dot(p, up));
    std::sort(heights.begin(), heights.end());
    if (fraction <= 0.0) return heights.front();
    if (fraction >= 1.0) return heights.back();
    const double target = fraction * area_below(poly, up, heights.back());
    // Bisection over the sorted vertex heights: area(heights[lo]) < target <= area(heights[hi]).
    size_t lo = 0, hi = heights.size() - 1;
    double a_lo = 0.0, a_hi = area_below(poly, up, heights.back());
    while (hi - lo > 1) {
        const size_t mid = (lo + hi) / 2;
        const double a = area_below(poly, up, heights[mid]);
        if (a < target) lo = mid, a_lo = a;
        else hi = mid, a_hi = a;
    }
    // The area is quadratic in u = (h - h_lo) / (h_hi - h_lo): a_lo + b u + c u^2 through three points.
    const double h_lo = heights[lo], span = heights[hi] - h_lo;
    const double a_mid = area_below(poly, up, h_lo + 0.5 * span);
    const double b = 4.0 * (a_mid - a_lo) - (a_hi - a_lo);
    const double c = (a_hi - a_lo) - b;
    const double need = target - a_lo;
    // The root in [0, 1] of c u^2 + b u - need, in the form that does not cancel (b >= 0: the chord
    // at the bracket's bottom has non-negative length).
    const double disc = std::max(0.0, b * b + 4.0 * c * need);
    const double denom = b + std::sqrt(disc);
    const double u = denom > 0.0 ? std::clamp(2.0 * need / denom, 0.0, 1.0) : 0.5;
    return h_lo + u * span;
}

FillSegments fill_segments(const std::vector<Vec2>& inner, Vec2 up, double fraction, double density) {
    FillSegments f;
    f.up = up;
    f.level_m = fill_level(inner, up, fraction);
    if (fraction <= 0.0) return f;
    f.region = fraction >= 1.0 ? inner : geom::clip_half_plane(inner, up, f.level_m);
    // A fan from the first vertex: the region is convex, so every triangle lies inside it.
    double area = 0.0;
    Vec2 moment;
    std::vector<geom::AreaProperties> parts;
    for (size_t i = 1; i + 1 < f.region.size(); ++i) {
        const std::array<Vec2, 3> t = {f.region[0], f.region[i], f.region[i + 1]};
        const geom::AreaProperties p = geom::triangle_properties(t[0], t[1], t[2]);
        if (p.area <= 0.0) continue;  // a sliver where the surface passes through a vertex
        f.triangles.push_back(t);
        parts.push_back(p);
        area += p.area;
        moment = moment + p.area * p.centroid;
    }
    if (area <= 0.0) return f;
    f.mass.mass_kg = density * area;
    f.mass.centre_of_mass_m = (1.0 / area) * moment;
    for (const geom::AreaProperties& p : parts) {
        const Vec2 d = p.centroid - f.mass.centre_of_mass_m;
        f.mass.inertia_cm_kg_m2 += density * (p.polar_moment_cm + p.area * geom::dot(d, d));
    }
    return f;
}

}  // namespace polyroll::models
