// Derived shell properties: see shell_properties.h.
#include "sim/geometry/shell_properties.h"

#include <cmath>

#include "sim/geometry/geometry.h"

namespace polyroll {

ShellProperties shell_properties(const ShellParams& s) {
    using namespace geom;
    ShellProperties p;
    const int n = s.sides;
    p.sides = n;
    p.inner_circumradius_m = s.inner_circumradius_m;
    p.inner_apothem_m = regular_polygon_apothem(n, s.inner_circumradius_m);
    // The wall thickness is perpendicular to each face, so the apothem grows by it.
    p.outer_apothem_m = p.inner_apothem_m + s.wall_thickness_m;
    p.outer_circumradius_m = p.outer_apothem_m / std::cos(kPi / n);
    p.outer_side_m = regular_polygon_side(n, p.outer_circumradius_m);

    const double a_in = regular_polygon_area(n, s.inner_circumradius_m);
    const double a_out = regular_polygon_area(n, p.outer_circumradius_m);
    const double j_in = regular_polygon_polar_moment(n, s.inner_circumradius_m);
    const double j_out = regular_polygon_polar_moment(n, p.outer_circumradius_m);
    p.inner_area_m2 = a_in;
    p.inside_volume_m3 = a_in * s.depth_m;
    p.wall_volume_m3 = (a_out - a_in) * s.depth_m;
    // Each lid closes the whole outer outline.
    p.lid_volume_m3 = 2.0 * a_out * s.lid_thickness_m;

    p.mass_kg = s.mass_kg;
    p.lid_mass_fraction = s.lid_mass_fraction.value_or(p.lid_volume_m3 / (p.lid_volume_m3 + p.wall_volume_m3));
    const double m_lids = p.lid_mass_fraction * s.mass_kg;
    const double m_walls = s.mass_kg - m_lids;
    // A prism's moment about its axis is its mass times (polar moment / area) of its cross-section.
    const double i_walls = m_walls * (j_out - j_in) / (a_out - a_in);
    const double i_lids = m_lids * j_out / a_out;
    p.inertia_kg_m2 = i_walls + i_lids;
    p.lid_inertia_share = p.inertia_kg_m2 > 0.0 ? i_lids / p.inertia_kg_m2 : 0.0;
    p.pivot_radius_m = p.outer_circumradius_m;
    return p;
}

double rigid_impact_energy_ratio(int sides, double mass_kg, double inertia_kg_m2, double pivot_radius_m) {
    const double mr2 = mass_kg * pivot_radius_m * pivot_radius_m;
    const double w_ratio = (inertia_kg_m2 + mr2 * std::cos(2.0 * geom::kPi / sides)) / (inertia_kg_m2 + mr2);
    return w_ratio * w_ratio;
}

}  // namespace polyroll
