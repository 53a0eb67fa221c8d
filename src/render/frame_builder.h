// Builds the draw list of one frame from a snapshot: the world through the main camera (the whole
// ramp, or following the shell), the close-up inset, the overlay panel and the speed plot.
// No GL: gl_renderer draws the list offscreen, and tests read it directly. The sandbox's window
// builds its own list (app/scene_view.h) from the same view layer (camera.h's framings,
// view_style.h, world_draw.h, close_up.h, ticks.h) with its own cameras, and draws it with the same
// renderer.
#pragma once

#include "render/camera.h"
#include "render/draw_list.h"
#include "render/font.h"
#include "render/frame_layout.h"
#include "render/snapshot.h"

namespace polyroll::render {

// The camera the main view uses for this snapshot.
Camera main_camera(const Snapshot& s, const FrameOptions& o, const FrameLayout& L);

DrawList build_frame(const Snapshot& s, const FrameOptions& o, const FontAtlas& font);

}  // namespace polyroll::render
