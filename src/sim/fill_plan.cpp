// Grain packing before release: see fill_plan.h.
#include "sim/fill_plan.h"

#include <algorithm>
#include <cmath>

#include "sim/rng.h"

namespace polyroll {

using geom::Vec2;

namespace {
// Vertex 0 at -90 - 180/n degrees puts face (0, 1) at the bottom, level.
double first_vertex_angle(int sides) { return -geom::kPi / 2.0 - geom::kPi / sides; }
}  // namespace

std::vector<Vec2> shell_inner_polygon_m(const ShellParams& s) {
    return geom::regular_polygon(s.sides, s.inner_circumradius_m, first_vertex_angle(s.sides));
}

std::vector<Vec2> shell_outer_polygon_m(const ShellParams& s) {
    const ShellProperties p = shell_properties(s);
    return geom::regular_polygon(s.sides, p.outer_circumradius_m, first_vertex_angle(s.sides));
}

FillPlan plan_fill(const Scene& scene, const ShellProperties& shell, Vec2 up) {
    FillPlan plan;
    plan.up = up;
    const double r = scene.fill.ratio;
    const MaterialParams& m = scene.fill.material;
    plan.target_mass_kg = r * shell.inside_volume_m3 * m.bulk_density_kg_m3;
    const std::vector<Vec2> inner = shell_inner_polygon_m(scene.shell);
    plan.surface_level_m = geom::level_for_area_fraction(inner, up, r);
    if (r <= 0.0) return plan;

    const double r_max = 0.5 * m.diameter_m * (1.0 + m.diameter_spread);
    const double spacing = 2.0 * r_max * 1.02;  // 2% gap so no two grains start overlapping
    const double clearance = 1.03 * r_max;      // from every wall, beyond the jitter
    const double jitter = 0.005 * m.diameter_m; // stays inside the gap
    const Vec2 right = {up.y, -up.x};           // level direction

    double lo = 1e300, hi = -1e300, left = 1e300, rightmost = -1e300;
    for (const Vec2& v : inner) {
        lo = std::min(lo, geom::dot(v, up));
        hi = std::max(hi, geom::dot(v, up));
        left = std::min(left, geom::dot(v, right));
        rightmost = std::max(rightmost, geom::dot(v, right));
    }
    Rng rng(scene.run.seed);
    struct Site {
        Vec2 p;
        double height;
    };
    std::vector<Site> sites, all_sites;
    const double row_step = spacing * std::sqrt(3.0) / 2.0;
    int row = 0;
    for (double h = lo + clearance; h <= hi; h += row_step, ++row) {
        const double offset = (row % 2) ? spacing / 2.0 : 0.0;
        for (double w = left + offset; w <= rightmost; w += spacing) {
            const Vec2 p = h * up + w * right;
            if (geom::inside_distance(inner, p) < clearance) continue;
            all_sites.push_back({p, h});
            if (h <= plan.surface_level_m) sites.push_back({p, h});
        }
    }
    if (sites.empty()) {
        // A fill too small for one lattice site still has its mass: one grain at the lowest site,
        // or at the centre when even the lattice misses (grains nearly as wide as the inside).
        if (!all_sites.empty())
            sites.push_back(*std::min_element(all_sites.begin(), all_sites.end(),
                                              [](const Site& a, const Site& b) { return a.height < b.height; }));
        else
            sites.push_back({Vec2{0.0, 0.0}, 0.0});
    }
    double area_sum = 0.0;
    for (const Site& s : sites) {
        PlannedGrain g;
        g.radius_m = 0.5 * m.diameter_m * (1.0 + m.diameter_spread * rng.uniform(-1.0, 1.0));
        g.position_m = s.p + Vec2{rng.uniform(-jitter, jitter), rng.uniform(-jitter, jitter)};
        area_sum += g.radius_m * g.radius_m;
        plan.grains.push_back(g);
    }
    for (PlannedGrain& g : plan.grains) g.mass_kg = plan.target_mass_kg * g.radius_m * g.radius_m / area_sum;
    return plan;
}

}  // namespace polyroll
