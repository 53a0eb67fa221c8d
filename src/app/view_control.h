// The scene view's camera (the lanes' stacked ramps, pan and zoom), now in the renderer
// (render/view_control.h) beside the scene view that uses it; the window's names for it.
#pragma once

#include "render/view_control.h"

namespace polyroll::app {

using render::kMaxZoom;
using render::kMinZoom;
using render::lane_layout;
using render::LaneLayout;
using render::ViewTransform;

}  // namespace polyroll::app
