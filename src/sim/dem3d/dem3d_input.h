// What the 3D reference's script (polyroll_dem3d.py) is given: the scene resolved into the numbers a
// 3D box needs, in the ramp frame of world_builder.h (x down the slope, y along its normal, z the roll
// axis). The polygon's vertices, the release pose and the end of the run come from the same functions
// the 2D models use, so both models start from the same pose and end at the same place.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "sim/scene/scene.h"

namespace polyroll::dem3d {

// The radius of the spheres along the box's outer edges: the shell's vertex rounding
// (shell.vertex_radius_m), at least the 0.1 mm this engine can make.
double edge_sphere_radius_m(const Scene& scene);

// The script's input; `frames_hz` > 0 asks for the grains' positions at that rate (for drawing).
nlohmann::ordered_json script_input(const Scene& scene, double frames_hz);

}  // namespace polyroll::dem3d
