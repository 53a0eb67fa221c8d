// Framing the ramp and following the shell: see camera.h.
#include "render/camera.h"

#include <algorithm>
#include <cmath>

namespace polyroll::render {

ClipRect covering_pixels(const PxRect& r) {
    const int x0 = static_cast<int>(std::floor(r.x)), y0 = static_cast<int>(std::floor(r.y));
    return {x0, y0, static_cast<int>(std::ceil(r.x + r.width)) - x0, static_cast<int>(std::ceil(r.y + r.height)) - y0};
}

geom::Vec2 ramp_to_world(geom::Vec2 ramp_m, double angle_deg) {
    // Down the slope is down and to the right: a clockwise turn by the ramp angle.
    return geom::rotate(ramp_m, -angle_deg * geom::kPi / 180.0);
}

Camera whole_ramp_camera(double ramp_length_m, double angle_deg, double clearance_m, PxRect area) {
    // The lab-frame box around the ramp surface and the space the shell needs above it.
    const geom::Vec2 pts[4] = {ramp_to_world({0.0, 0.0}, angle_deg),
                               ramp_to_world({ramp_length_m, 0.0}, angle_deg),
                               ramp_to_world({0.0, clearance_m}, angle_deg),
                               ramp_to_world({ramp_length_m, clearance_m}, angle_deg)};
    double lo_x = pts[0].x, hi_x = pts[0].x, lo_y = pts[0].y, hi_y = pts[0].y;
    for (const geom::Vec2& p : pts) {
        lo_x = std::min(lo_x, p.x);
        hi_x = std::max(hi_x, p.x);
        lo_y = std::min(lo_y, p.y);
        hi_y = std::max(hi_y, p.y);
    }
    const double w = std::max(hi_x - lo_x, 1e-6), h = std::max(hi_y - lo_y, 1e-6);
    Camera cam;
    cam.px_per_m = std::min(area.width / w, area.height / h);
    cam.centre_m = {(lo_x + hi_x) / 2.0, hi_y};
    cam.anchor = {area.x + area.width / 2.0f, area.y};
    return cam;
}

Camera follow_camera(geom::Vec2 shell_centre_ramp_m, double angle_deg, double radius_m, double radius_share,
                     PxRect area) {
    Camera cam;
    cam.px_per_m = radius_share * area.height / std::max(radius_m, 1e-9);
    cam.centre_m = ramp_to_world(shell_centre_ramp_m, angle_deg);
    cam.anchor = {area.x + area.width / 2.0f, area.y + area.height / 2.0f};
    return cam;
}

Camera follow_framing(geom::Vec2 shell_centre_ramp_m, double angle_deg, double radius_m, PxRect area,
                      double picture_height_px) {
    return follow_camera(shell_centre_ramp_m, angle_deg, radius_m, kFollowRadiusShare * picture_height_px / area.height,
                         area);
}

}  // namespace polyroll::render
