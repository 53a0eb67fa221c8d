// Draws the physical scene of a snapshot through a camera: the ramp at its angle with its length
// scale, the shell (inside, walls, outline), the grains and the tracked lid dot, in a style from
// view_style.h: the frames and the window draw their worlds with this one function.
#pragma once

#include "render/camera.h"
#include "render/draw_list.h"
#include "render/font.h"
#include "render/snapshot.h"
#include "render/view_style.h"

namespace polyroll::render {

void draw_world(const Snapshot& s, const Camera& cam, const WorldStyle& style, const FontAtlas& font, Layer& out);

// The shell's vertices in the lab frame (outer or inner polygon).
std::vector<geom::Vec2> shell_world_polygon(const Snapshot& s, bool outer);

// The shell's outer radius: its farthest outer vertex from its centre. The cameras frame the polygon
// by it (the whole ramp's clearance, following, the close-up).
double outer_radius_m(const Snapshot& s);

// The grain fill colour for a grain of the snapshot.
Rgba grain_colour(const Snapshot& s, const GrainState& g, GrainColouring how, double speed_max_m_s);

}  // namespace polyroll::render
