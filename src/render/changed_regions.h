// Where a frame's draw list differs from the last one's, in pixels: the window redraws only there
// when its back buffer still holds the last frame (a software GL showing parts of a back buffer it
// never swaps, app/sandbox_window.h). In `hexagon-large-bb` the ramp's view is still but for the
// shell and its pile, and the scene's clear alone was half its GL time under llvmpipe: a scissored
// clear is a quad shaded over every pixel (docs/sandbox.md, "The scene drawn where it changed").
//
// The rule is exact: a pixel outside every region is covered only by primitives equal, in value and
// in their place in the list, to the last frame's, so drawing the whole list again would give it the
// same value. Inside a region the renderer clears and draws every primitive that reaches it, in the
// list's order (gl_renderer.h), so a frame drawn in regions is the frame drawn whole, pixel for pixel.
#pragma once

#include <optional>
#include <vector>

#include "render/draw_list.h"

namespace polyroll::render {

// The pixels a primitive can touch when drawn (its antialiasing fringe included), rows from the top.
ClipRect pixels_touched(const Triangle& t);
ClipRect pixels_touched(const Shape& s);
ClipRect pixels_touched(const GlyphQuad& g);

ClipRect intersection(const ClipRect& a, const ClipRect& b);
bool overlap(const ClipRect& a, const ClipRect& b);

// The regions where `now` differs from `before`, each inside the layer it comes from (and the list's
// bounds), merged into a few rectangles. Empty: nothing changed. None: the two lists differ in their
// frame (size, background, bounds, font atlas, layers or their clips): draw it whole.
std::optional<std::vector<ClipRect>> changed_regions(const DrawList& before, const DrawList& now);

// The pixels each item of each layer can touch (pixels_touched), in the list's order. Measured once a
// frame for all that ask (the regions' growth and the renderer's culling): a big pile has thousands
// of discs, and measured again in every pass and region they were a fifth of the window's UI thread
// in hexagon-large-bb (docs/sandbox.md).
struct LayerPixels {
    std::vector<ClipRect> triangles, shapes, glyphs;
};
std::vector<LayerPixels> pixels_of(const DrawList& list);

// Grows each region until every disc that reaches into it lies in it whole, then merges them again.
// llvmpipe keeps a point sprite to the scissor only block by block (4x4 pixels): a sprite crossing a
// region's edge may be blended again onto a row just outside it, over the last frame's pixel there,
// which a whole redraw would not do (measured: one row of 17 pixels darker after the stops-abruptly
// preset's pile came to rest). With no sprite crossing an edge, nothing is drawn outside the regions.
// Small discs are not sprites but one image cut to the region (disc_splat.h): they need no room.
// `pixels`: pixels_of(list).
void hold_whole_discs(const DrawList& list, const std::vector<LayerPixels>& pixels, std::vector<ClipRect>& regions);

// Adds `r` to `regions`, merging rectangles where one rectangle around both is little larger than
// the two (the renderer sends each region the primitives that reach it, so fewer, slightly larger
// regions are cheaper than many small ones). Regions may overlap: each is cleared and drawn whole,
// so a pixel in two is drawn twice to the same value. Past a few regions, one around all.
void add_region(std::vector<ClipRect>& regions, const ClipRect& r);

}  // namespace polyroll::render
