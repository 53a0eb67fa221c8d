// The draw-list tests' hand-made snapshot: a square shell (outer radius 4 cm, inner 3.5 cm) on a 1 m
// ramp at 30 degrees, with three BBs, half a second into a run. Tests change what they test on it.
#pragma once

#include <cmath>

#include "render/snapshot.h"
#include "sim/geometry/geometry.h"

namespace polyroll::test {

inline render::Snapshot known_snapshot() {
    render::Snapshot s;
    s.sides = 4;
    s.fill_ratio = 0.25;
    s.ramp_angle_deg = 30.0;
    s.ramp_length_m = 1.0;
    s.material = "bb";
    s.outer_local_m = geom::regular_polygon(4, 0.04, -geom::kPi / 4);
    s.inner_local_m = geom::regular_polygon(4, 0.035, -geom::kPi / 4);
    s.time_s = 0.5;
    s.shell_centre_m = {0.4, 0.04 * std::cos(geom::kPi / 4)};
    s.shell_angle_rad = 0.1;
    s.grains = {{{0.39, 0.012}, 0.003, 0.1}, {{0.41, 0.012}, 0.003, 0.2}, {{0.40, 0.018}, 0.004, 0.3}};
    s.now.time_s = 0.5;
    s.now.position_m = 0.3;
    s.now.speed_m_s = 0.42;
    s.impacts = 3;
    s.speed_history = {{0.0, 0.0}, {0.25, 0.3}, {0.5, 0.42}};
    return s;
}

}  // namespace polyroll::test
