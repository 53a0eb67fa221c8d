// A snapshot: the state of a run at one instant, in SI units (metres in the ramp frame: x down the
// slope, y along its normal, surface at y = 0), whatever the model. It is all a frame or the window
// needs, so drawing never touches the engine and a snapshot can be built by hand in tests. Each model
// builds its own (ModelRun::snapshot); the parts every model shares are built here.
#pragma once

#include <string>
#include <vector>

#include "sim/geometry/geometry.h"
#include "sim/measurements.h"
#include "sim/scene/scene.h"

namespace polyroll {

struct GrainState {
    geom::Vec2 position_m;
    double radius_m = 0.0;
    double speed_m_s = 0.0;
    // A 3D grain (--model dem3d) projected on the cross-section: where it lies across the box, 0 at
    // the lid nearest the viewer to 1 at the far one. Negative for a 2D disc.
    double depth = -1.0;
};

// One point of the speed-versus-time plot.
struct SpeedPoint {
    double time_s = 0.0;
    double speed_m_s = 0.0;
};

struct RunSnapshot {
    // The scene's parameters, for the layout and the overlay.
    int sides = 0;
    double fill_ratio = 0.0;
    double ramp_angle_deg = 0.0;
    double ramp_length_m = 0.0;
    std::string material;  // preset name ("" for a custom material)
    std::string ramp;      // preset name
    std::vector<geom::Vec2> outer_local_m;  // the shell's polygons in its own frame
    std::vector<geom::Vec2> inner_local_m;

    // The state.
    double time_s = 0.0;  // since release
    geom::Vec2 shell_centre_m;
    double shell_angle_rad = 0.0;  // counter-clockwise in the ramp frame
    std::vector<GrainState> grains;
    // The fill as one region, in the shell's own frame (counter-clockwise), where the model holds it
    // as a body rather than as grains: the whole inside of a full shell, the rigid model's fill frozen
    // as at release, the segment model's levelled at its last impact. Empty where grains are drawn
    // one by one, or there is no fill.
    std::vector<geom::Vec2> fill_region_local_m;
    TrajectorySample now;  // the tracker's latest measurement (position, speed)
    int impacts = 0;
    std::vector<SpeedPoint> speed_history;  // the tracker's samples so far
};

// The scene's part of a snapshot, with the shell's polygons.
RunSnapshot scene_snapshot(const Scene& scene, const std::vector<geom::Vec2>& outer_local_m,
                           const std::vector<geom::Vec2>& inner_local_m);

// The measurements' part: the latest sample, the impacts so far and the speed history, which ends at
// the current instant even between trajectory samples.
void set_measured(RunSnapshot& s, const TrajectorySample& now, const Measurements& m);

}  // namespace polyroll
