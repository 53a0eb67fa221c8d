// Friction of the grains on the two lids (end faces). A 2D disc stands for a column of grains
// along the roll axis; in the real box the column's ends press on the lids with the pile's lateral
// pressure and rub on them whenever the fill slides relative to the shell, which no contact in the
// plane gives. Applied each engine step as a pair of impulses, on the grain and (opposite) on the
// shell at the grain, so it only ever removes energy of relative motion. See docs/physics.md.
#pragma once

#include "sim/grains/world_builder.h"

namespace polyroll {

// The lateral-to-vertical stress ratio of a pile at rest (Jaky's K0 = 1 - sin(phi), with phi the
// angle of internal friction, atan of the grain-on-grain friction).
double lateral_pressure_ratio(double grain_friction);

// The normal force of one grain's column on both lids, in newtons: its weight times
// 2 K h / depth, with h how deep it lies below the top of the pile (along gravity).
double lid_normal_force_n(double grain_mass_kg, double gravity_m_s2, double depth_below_top_m, double shell_depth_m,
                          double lateral_ratio);

// The per-step hook (force_hook.h): lid friction on every grain of `w` for one engine step.
void apply_lid_friction(SimWorld& w, double engine_step_s);

}  // namespace polyroll
