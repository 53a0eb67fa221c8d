// Draws the physical scene of a snapshot through a camera: the ramp at its angle with its length
// scale, the shell (inside, walls, outline), the grains and the tracked lid dot.
#pragma once

#include "render/camera.h"
#include "render/draw_list.h"
#include "render/font.h"
#include "render/frame_layout.h"
#include "render/snapshot.h"

namespace polyroll::render {

struct WorldStyle {
    float unit = 1.0f;    // design pixel
    float stroke = 2.5f;  // outline width
    FontSpec scale_font;
    PxRect visible;       // only ticks inside this rectangle are drawn
    GrainColouring grain_colouring = GrainColouring::material;
    double colour_speed_max_m_s = 1.0;
};

void draw_world(const Snapshot& s, const Camera& cam, const WorldStyle& style, const FontAtlas& font, Layer& out);

// The shell's vertices in the lab frame (outer or inner polygon).
std::vector<geom::Vec2> shell_world_polygon(const Snapshot& s, bool outer);

// The shell's outer radius: its farthest outer vertex from its centre. The cameras frame the polygon
// by it (the whole ramp's clearance, following, the close-up).
double outer_radius_m(const Snapshot& s);

// The grain fill colour for a grain of the snapshot.
Rgba grain_colour(const Snapshot& s, const GrainState& g, GrainColouring how, double speed_max_m_s);

}  // namespace polyroll::render
