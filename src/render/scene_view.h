// The sandbox's scene view as a draw list (GL-free): what a frame draws (the world and the close-up,
// in render/view_style.h's style) for each lane through the lane's camera (view_control.h), clipped
// to the view, plus the lanes' badges in their colours when racing. The window draws it with
// render::GlRenderer (app/scene_view.h names it there), and polyroll render --preset draws a race's
// frames with it (race_frame.h), so a rendered race shows its lanes as the window does.
#pragma once

#include <vector>

#include "render/view_control.h"
#include "render/draw_list.h"
#include "render/font.h"
#include "render/snapshot.h"
#include "render/view_style.h"

namespace polyroll::render {

struct SceneViewOptions {
    int width_px = 0, height_px = 0;  // the whole framebuffer
    render::PxRect area;              // the part the scene fills (the rest is under the panels)
    float unit = 1.0f;                // design pixel: the UI scale
    bool follow = false;
    render::GrainColouring colouring = render::GrainColouring::material;
    double colour_speed_max_m_s = 1.0;
    ViewTransform view;
    // Whole-ramp view: a close-up of this lane's polygon in the free corner under the ramp
    // (-1 for none). The polygon is small on a 2.5 m ramp; the close-up shows its grains.
    int close_up_lane = 0;
    // Draw nothing outside the area's pixels, not even the clear: the window keeps the panels'
    // pixels there from frame to frame (app/panel_cache.h). Otherwise the whole frame is cleared.
    bool area_only = false;
};

// The font sizes the view uses at a UI scale (the atlas must hold them).
std::vector<render::FontSpec> scene_view_fonts(float unit);

// Each lane's colour: its label, its plot trace and its readout column share it.
render::Rgba lane_colour(size_t lane);

// Where the view put what must stay visible, in framebuffer pixels, for the layout checks
// (polyroll-sandbox --layout-report): each lane's release point (its ramp's upper end) and badge,
// and the close-up.
struct SceneViewBoxes {
    std::vector<render::Px> ramp_starts;
    std::vector<render::PxRect> badges;
    std::vector<render::PxRect> close_up;  // none or one
};

render::DrawList build_scene_view(const std::vector<render::Snapshot>& lanes, const SceneViewOptions& o,
                                  const render::FontAtlas& font,
                                  SceneViewBoxes* boxes = nullptr);

}  // namespace polyroll::render
