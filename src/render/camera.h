// The camera: where the world appears in the frame. The picture's world frame is the lab's (x to the
// right, y up, metres), with the ramp drawn at its angle going down to the right; the simulation's
// ramp frame is turned into it by ramp_to_world. Two framings: the whole ramp, or following the shell;
// the frames and the sandbox's window both frame with these, each in its own area.
#pragma once

#include "render/draw_list.h"
#include "sim/geometry/geometry.h"

namespace polyroll::render {

// A rectangle of the frame, in pixels (top-left origin).
struct PxRect {
    float x = 0.0f, y = 0.0f, width = 0.0f, height = 0.0f;
};

// The whole pixels a rectangle touches (its edges widened outwards to pixel boundaries).
ClipRect covering_pixels(const PxRect& r);

// The ramp frame (x down the slope, y normal to it) turned into the lab frame for a ramp at angle_deg.
geom::Vec2 ramp_to_world(geom::Vec2 ramp_m, double angle_deg);

struct Camera {
    geom::Vec2 centre_m;     // lab point shown at `anchor`
    Px anchor;               // pixel where centre_m appears
    double px_per_m = 1.0;

    Px to_px(geom::Vec2 world_m) const {
        return {static_cast<float>(anchor.x + (world_m.x - centre_m.x) * px_per_m),
                static_cast<float>(anchor.y - (world_m.y - centre_m.y) * px_per_m)};
    }
    float to_px_length(double metres) const { return static_cast<float>(metres * px_per_m); }
};

// Fits the whole ramp (surface from x = 0 to length, plus `clearance_m` above it for the shell) into
// `area`, centred horizontally and against the top of the area, so the space below the ramp's
// upper end stays free for an inset.
Camera whole_ramp_camera(double ramp_length_m, double angle_deg, double clearance_m, PxRect area);

// Keeps the shell's centre (ramp frame) at the middle of `area`, scaled so that a circle of
// `radius_m` spans `radius_share` of the area's height.
Camera follow_camera(geom::Vec2 shell_centre_ramp_m, double angle_deg, double radius_m, double radius_share,
                     PxRect area);

// Share of the picture's height the shell's outer radius spans when the camera follows it, in the
// frames and the window alike. 0.24, the frames' value (the window had 0.28): at 0.28 a 16:9 frame's
// polygon would span 403 of its world area's 404 design pixels, and the window's one-lane view cut
// the ramp's scale labels off at the bottom.
inline constexpr double kFollowRadiusShare = 0.24;

// The follow framing: the shell's centre at the middle of `area` (what the overlays leave free), at
// the scale where `radius_m` spans kFollowRadiusShare of `picture_height_px` (a frame's height; one
// lane's strip of the window), so the zoom does not depend on the overlays' size.
Camera follow_framing(geom::Vec2 shell_centre_ramp_m, double angle_deg, double radius_m, PxRect area,
                      double picture_height_px);

}  // namespace polyroll::render
