// Builds the draw list of one frame from a snapshot: the world through the main camera (the whole
// ramp, or following the shell), the close-up inset, the overlay panel and the speed plot.
// No GL: the same list is drawn offscreen and (later) in the window, and tests read it directly.
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
