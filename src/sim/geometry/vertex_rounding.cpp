// The shell's rounded outer vertices: see vertex_rounding.h.
#include "sim/geometry/vertex_rounding.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/geometry/shell_outline.h"

namespace polyroll {

std::vector<geom::Vec2> vertex_arc_centres_m(const ShellParams& shell) {
    std::vector<geom::Vec2> centres = shell_outer_polygon_m(shell);
    const double inset = vertex_arc_inset_m(shell.sides, shell.vertex_radius_m);
    for (geom::Vec2& v : centres) v = (1.0 - inset / geom::length(v)) * v;
    return centres;
}

double vertex_rounding_drop_m(const ShellParams& shell, double angle_rad) {
    const std::vector<geom::Vec2> sharp = shell_outer_polygon_m(shell);
    const std::vector<geom::Vec2> arcs = vertex_arc_centres_m(shell);
    double sharp_low = std::numeric_limits<double>::infinity(), round_low = sharp_low;
    for (size_t i = 0; i < sharp.size(); ++i) {
        sharp_low = std::min(sharp_low, geom::rotate(sharp[i], angle_rad).y);
        round_low = std::min(round_low, geom::rotate(arcs[i], angle_rad).y - shell.vertex_radius_m);
    }
    // The rounded outline lies inside the sharp one, and the lowest point of the rounded outline is
    // on an arc (each face's lowest point is an end of its straight part, which lies on an arc).
    return std::max(0.0, round_low - sharp_low);
}

}  // namespace polyroll
