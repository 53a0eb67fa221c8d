// Pan, zoom and the lanes' framing: see view_control.h.
#include "render/view_control.h"

#include <algorithm>
#include <cmath>

#include "render/view_style.h"
#include "render/world_draw.h"

namespace polyroll::render {

namespace {

Px centre_of(const PxRect& a) { return {a.x + a.width / 2.0f, a.y + a.height / 2.0f}; }

// Room past each end of a ramp for half of its distance label ("0 m", "2.5 m") and a little air,
// in design pixels: without it the "0 m" at the ramp's top end sat half behind the panel.
constexpr float kLabelMarginDesignPx = 30.0f;
// Room above the surface for a lane's polygon, in outer radii (it may rock onto a vertex).
constexpr double kClearanceRadii = 2.4;
// Halvings of the stacked lanes' spacing interval: well under a pixel from any start.
constexpr int kSpacingBisections = 30;

}  // namespace

void ViewTransform::pan_by(double dx, double dy) {
    pan_x_px += dx;
    pan_y_px += dy;
}

void ViewTransform::zoom_at(Px at, double factor, const PxRect& area) {
    const double z = std::clamp(zoom * factor, kMinZoom, kMaxZoom);
    const double f = z / zoom;
    const Px c = centre_of(area);
    // The point under `at` stays put: at = c + zoom * (b - c) + pan before and after.
    pan_x_px = (at.x - c.x) - f * (at.x - c.x - pan_x_px);
    pan_y_px = (at.y - c.y) - f * (at.y - c.y - pan_y_px);
    zoom = z;
}

Camera ViewTransform::apply(const Camera& framed, const PxRect& area) const {
    const Px c = centre_of(area);
    Camera cam = framed;
    cam.px_per_m = framed.px_per_m * zoom;
    cam.anchor = {static_cast<float>(c.x + zoom * (framed.anchor.x - c.x) + pan_x_px),
                  static_cast<float>(c.y + zoom * (framed.anchor.y - c.y) + pan_y_px)};
    return cam;
}

LaneLayout lane_layout(const std::vector<render::Snapshot>& lanes, const PxRect& area, bool follow, float unit,
                       const ViewTransform& view) {
    LaneLayout out;
    if (lanes.empty()) return out;
    const size_t n = lanes.size();
    double radius = 0.0;
    for (const auto& s : lanes) radius = std::max(radius, render::outer_radius_m(s));
    const float band = render::kRampBelowDesignPx * unit;  // the body and labels under a ramp

    if (follow) {
        // Every lane in its own strip, one shared camera centred on the leading polygon, so the
        // race's gaps show as horizontal offsets; each strip is framed as a frame is (its own picture).
        size_t lead = 0;
        for (size_t i = 1; i < n; ++i)
            if (lanes[i].shell_centre_m.x > lanes[lead].shell_centre_m.x) lead = i;
        const float strip = area.height / static_cast<float>(n);
        const PxRect first{area.x, area.y, area.width, strip};
        const Camera base =
            render::follow_framing(lanes[lead].shell_centre_m, lanes[lead].ramp_angle_deg, radius, first, strip);
        out.lane_spacing_px = strip;
        for (size_t i = 0; i < n; ++i) {
            Camera c = base;
            c.anchor.y += static_cast<float>(i) * strip;
            out.cameras.push_back(view.apply(c, area));
        }
        return out;
    }

    // Whole ramps, stacked: the first ramp fitted into the area less the room the lanes below need,
    // each lane shifted down by the spacing. The lane badges' room is the caller's (scene_view.cpp
    // fits the ramps into the view less it); here only the distance labels' room at either end.
    const auto& s0 = lanes.front();
    const auto fit_with = [&](float spacing) {
        PxRect fit = area;
        const float margin = kLabelMarginDesignPx * unit;
        fit.x += margin;
        fit.width = std::max(1.0f, fit.width - 2.0f * margin);
        fit.height = std::max(1.0f, area.height - static_cast<float>(n - 1) * spacing - (n > 1 ? band : 0.0f));
        return render::whole_ramp_camera(s0.ramp_length_m, s0.ramp_angle_deg, kClearanceRadii * radius, fit);
    };
    // The spacing a framing needs: room for a polygon above the ramp, and the band under the ramp above.
    const auto needed = [&](const Camera& c) {
        return static_cast<float>(kClearanceRadii * radius * c.px_per_m) + band;
    };
    Camera base = fit_with(0.0f);
    float spacing = 0.0f;
    if (n > 1) {
        // The spacing grows with the scale and the scale shrinks as the spacing grows: the smallest
        // spacing that is enough, by bisection, so no height is left unused under the lowest lane.
        float lo = band, hi = needed(fit_with(band));
        for (int i = 0; i < kSpacingBisections; ++i) {
            const float mid = 0.5f * (lo + hi);
            if (needed(fit_with(mid)) > mid) lo = mid;
            else hi = mid;
        }
        spacing = hi;
        base = fit_with(spacing);
    }
    out.lane_spacing_px = n > 1 ? spacing : 0.0f;
    for (size_t i = 0; i < n; ++i) {
        Camera c = base;
        c.anchor.y += static_cast<float>(i) * spacing;
        out.cameras.push_back(view.apply(c, area));
    }
    return out;
}

}  // namespace polyroll::render
