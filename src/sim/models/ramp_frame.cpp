// The ramp frame of a scene: see ramp_frame.h.
#include "sim/models/ramp_frame.h"

#include "sim/shell_pose.h"
#include "sim/shell_properties.h"

namespace polyroll::models {

RampFrame ramp_frame(const Scene& scene) {
    const ShellProperties sp = shell_properties(scene.shell);
    RampFrame f;
    f.angle_deg = scene.ramp.angle_deg;
    f.gravity_m_s2 = scene.run.gravity_m_s2;
    f.friction = scene.ramp.friction;
    f.end_centre_x_m = end_centre_x_m(scene, sp);
    f.time_limit_s = scene.run.time_limit_s;
    f.sample_hz = scene.run.sample_hz;
    f.sample_grid_hz = scene.fidelity.step_hz;
    f.rest_speed_m_s = scene.run.rest_speed_m_s;
    f.rest_time_s = scene.run.rest_time_s;
    f.start_rotation_rad = -release_pose(scene, sp).angle_rad;
    // A full shell's fill is the whole inside however it was poured: only a partial fill is tipped.
    if (scene.release.pose == ReleasePose::tipped && scene.fill.ratio > 0.0 && scene.fill.ratio < 1.0) {
        f.pour_rotation_rad = -pour_pose(scene, sp).angle_rad;
        f.release_tilt_rad = scene.release.tilt_deg * geom::kPi / 180.0;
    }
    return f;
}

}  // namespace polyroll::models
