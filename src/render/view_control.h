// The scene view's camera, without a window: the lanes' parallel ramps stacked in the view (the
// whole ramps, or following the leading polygon with the frames' follow framing, render/camera.h),
// and the user's pan and zoom on top of that framing. Plain arithmetic on render::Camera, so it is
// tested without GL.
#pragma once

#include <vector>

#include "render/camera.h"
#include "render/snapshot.h"

namespace polyroll::render {

// The user's pan (pixels) and zoom (factor) about the view's centre, on top of the framing.
struct ViewTransform {
    double zoom = 1.0;
    double pan_x_px = 0.0, pan_y_px = 0.0;

    void pan_by(double dx_px, double dy_px);
    // Zooms by `factor` keeping the point under `at` where it is.
    void zoom_at(render::Px at, double factor, const render::PxRect& area);
    void reset() { *this = ViewTransform{}; }

    render::Camera apply(const render::Camera& framed, const render::PxRect& area) const;
};

inline constexpr double kMinZoom = 0.1, kMaxZoom = 200.0;  // past these the picture is a dot or a pixel

struct LaneLayout {
    std::vector<render::Camera> cameras;  // one per lane, with the user's transform applied
    float lane_spacing_px = 0.0f;         // vertical offset between the stacked ramps
};

// Stacks one ramp per snapshot in `area`, spaced so a lane's polygon clears the ramp above it.
// `follow`: the camera keeps the leading polygon in view (zoomed in); otherwise whole ramps.
// `unit` is the design pixel (the ramp's drawn body and labels scale with it). The whole-ramp framing
// leaves room at either end for the distance labels, and with several lanes none unused below the
// lowest; room for the lane badges is the caller's to take out of `area`.
LaneLayout lane_layout(const std::vector<render::Snapshot>& lanes, const render::PxRect& area, bool follow,
                       float unit, const ViewTransform& view);

}  // namespace polyroll::render
