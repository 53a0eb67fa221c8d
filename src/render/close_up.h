// The close-up inset: a second camera following the polygon, drawn in a framed rectangle over the
// main view, with a box in the main view marking where it looks. polyroll render's frames
// (frame_builder.cpp) and the sandbox's scene view (app/scene_view.cpp) draw it with this one
// function and style; they differ only in where it goes, and the window's lane colours and label.
#pragma once

#include <string>

#include "render/camera.h"
#include "render/draw_list.h"
#include "render/font.h"
#include "render/snapshot.h"
#include "render/world_draw.h"

namespace polyroll::render {

struct CloseUpStyle {
    PxRect rect;               // where the inset is drawn
    float unit = 1.0f;         // design pixel
    Rgba marker;               // the box in the main view
    Rgba border;               // the inset's frame
    FontSpec label_font;
    Px label_offset;           // the label's top left, from the inset's top left
    std::string label_suffix;  // after "close-up ×N" (N: the magnification over the main view)
};

// The close-up's look at a design unit, the same in the frames and the window: neutral colours, the
// scene's label font (view_style.h), the label inside the top-left corner. The caller places it in
// `rect` (each view has its own free corner); the window colours it by lane.
CloseUpStyle close_up_style(PxRect rect, float unit);

// Adds the mark (one layer over the main view seen through `main_cam`), then the inset: its
// background, `s`'s world drawn with `world` (only what falls inside the inset), its frame and label.
void draw_close_up(const Snapshot& s, const Camera& main_cam, const CloseUpStyle& style, WorldStyle world,
                   const FontAtlas& font, DrawList& dl);

}  // namespace polyroll::render
