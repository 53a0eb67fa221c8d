// Derived properties of the hollow polygon: outer geometry, volumes, mass split and the moment of
// inertia of the real 3D box about its roll axis, which the 2D body is given.
#pragma once

#include "sim/scene/scene.h"

namespace polyroll {

struct ShellProperties {
    int sides = 0;
    double inner_circumradius_m = 0.0;
    double inner_apothem_m = 0.0;
    double outer_circumradius_m = 0.0;  // centre to an outer vertex: the pivot when rolling
    double outer_apothem_m = 0.0;
    double outer_side_m = 0.0;
    double inner_area_m2 = 0.0;         // inside cross-section
    double inside_volume_m3 = 0.0;      // inner area times depth
    double wall_volume_m3 = 0.0;
    double lid_volume_m3 = 0.0;         // both lids
    double mass_kg = 0.0;
    double lid_mass_fraction = 0.0;     // as used (resolved from the volumes if not given)
    double inertia_kg_m2 = 0.0;         // about the centre of mass (the polygon's centre)
    double lid_inertia_share = 0.0;     // lids' part of inertia_kg_m2
    double pivot_radius_m = 0.0;        // outer vertex to centre of mass
};

ShellProperties shell_properties(const ShellParams& shell);

// The box's whole length along the roll axis: the inside depth and both lids.
inline double box_length_m(const ShellParams& shell) { return shell.depth_m + 2.0 * shell.lid_thickness_m; }

// The rigid impact model's kinetic-energy ratio over one face impact for a body symmetric about the
// polygon's centre (docs/physics.md): Q = ((I0 + M R^2 cos(2 pi/n)) / (I0 + M R^2))^2.
double rigid_impact_energy_ratio(int sides, double mass_kg, double inertia_kg_m2, double pivot_radius_m);

}  // namespace polyroll
