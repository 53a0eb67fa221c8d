// The shell's outlines: see shell_outline.h.
#include "sim/geometry/shell_outline.h"

#include "sim/geometry/shell_properties.h"

namespace polyroll {

namespace {
// Vertex 0 at -90 - 180/n degrees puts face (0, 1) at the bottom, level.
double first_vertex_angle(int sides) { return -geom::kPi / 2.0 - geom::kPi / sides; }
}  // namespace

std::vector<geom::Vec2> shell_inner_polygon_m(const ShellParams& s) {
    return geom::regular_polygon(s.sides, s.inner_circumradius_m, first_vertex_angle(s.sides));
}

std::vector<geom::Vec2> shell_outer_polygon_m(const ShellParams& s) {
    const ShellProperties p = shell_properties(s);
    return geom::regular_polygon(s.sides, p.outer_circumradius_m, first_vertex_angle(s.sides));
}

}  // namespace polyroll
