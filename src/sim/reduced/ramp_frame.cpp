// The ramp frame of a scene: see ramp_frame.h.
#include "sim/reduced/ramp_frame.h"

#include "sim/geometry/ramp_profile.h"
#include "sim/geometry/shell_pose.h"
#include "sim/geometry/shell_properties.h"

namespace polyroll::models {

namespace {
RampParams profile_of(const RampFrame& f) {
    RampParams r;
    r.angle_deg = f.angle_deg;
    r.curvature_deg_per_m = f.curvature_deg_per_m;
    r.length_m = f.track_length_m;
    return r;
}
}  // namespace

double RampFrame::slope_rad_at(double x_m) const {
    // As every model turned angle_deg before the track could curve, so a straight track is unchanged.
    return local_slope_deg(profile_of(*this), x_m) * geom::kPi / 180.0;
}

double RampFrame::height_at_m(double x_m, double y_m) const { return height_m(profile_of(*this), x_m, y_m); }

RampFrame ramp_frame(const Scene& scene) {
    const ShellProperties sp = shell_properties(scene.shell);
    RampFrame f;
    f.angle_deg = scene.ramp.angle_deg;
    f.curvature_deg_per_m = scene.ramp.curvature_deg_per_m;
    f.track_length_m = scene.ramp.length_m;
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
