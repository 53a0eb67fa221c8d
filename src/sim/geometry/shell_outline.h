// The shell's outlines in its own frame: the inner polygon the fill lies in and the outer one that
// touches the ramp. Every model (the grain engine, the reduced models, the 3D reference) lays its
// shell out from these, so vertex 0 means the same corner in all of them.
#pragma once

#include <vector>

#include "sim/geometry/geometry.h"
#include "sim/scene/scene.h"

namespace polyroll {

// The shell's inner polygon in its own frame (counter-clockwise), centred at the origin. Vertex 0
// and 1 span the face that lies on the ramp when the shell's angle is 0; vertex 1 is the downhill one.
std::vector<geom::Vec2> shell_inner_polygon_m(const ShellParams& shell);
// The outer polygon, laid out the same way (the inner one grown by the wall's thickness).
std::vector<geom::Vec2> shell_outer_polygon_m(const ShellParams& shell);

}  // namespace polyroll
