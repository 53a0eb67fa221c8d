// The sandbox's scene view: the lanes side by side as a draw list, now in the renderer
// (render/scene_view.h) so that polyroll render draws a race as the window does; the window's names
// for it.
#pragma once

#include "app/view_control.h"
#include "render/scene_view.h"

namespace polyroll::app {

using render::build_scene_view;
using render::lane_colour;
using render::scene_view_fonts;
using render::SceneViewBoxes;
using render::SceneViewOptions;

}  // namespace polyroll::app
