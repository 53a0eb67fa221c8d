// Small discs composited on the CPU into one image, which the renderer then draws as one textured quad
// (gl_renderer.h). A software GL (llvmpipe: the window under Xvfb and every headless frame) pays
// about 0.8 us for each point sprite however few pixels it covers: hexagon-large-bb's 2 x 1,709
// grains of a pixel or two cost it 2.8 ms a frame (docs/sandbox.md). Here each disc costs the handful
// of pixels it covers, and the GL one upload and one quad.
//
// The same picture as the sprites: each pixel's coverage and outline come from the sprites' own
// formula (the distance of the pixel's centre from the disc's, gl_renderer.cpp's disc_colour), and
// the discs are blended in order onto a transparent, premultiplied layer, which blended once onto the
// frame (ONE, ONE_MINUS_SRC_ALPHA) is what blending each disc onto it gives in exact arithmetic. What
// differs is where 8-bit rounding happens (once here, once a disc for the sprites): at most a level
// or two of 255 (tests/test_render_headless.cpp). GL-free, so it is tested without a context.
#pragma once

#include <cstdint>
#include <vector>

#include "render/draw_list.h"

namespace polyroll::render {

// The largest disc composited on the CPU. Its cost grows with its area (a disc of radius 4 px covers
// about 80 pixels with its fringe) where llvmpipe's sprite cost is mostly fixed and shades its
// pixels in parallel: larger discs (a close follow camera) stay sprites.
inline constexpr float kSplatMaxRadiusPx = 4.0f;

// Whether the renderer composites `s` here: a disc (a capsule of zero length) no larger than the
// above. Depends on the shape alone, never on where the frame is cut into regions, so a frame drawn
// in regions gets the same images as one drawn whole.
bool splat_eligible(const Shape& s);

// The composited discs: premultiplied RGBA, 8 bits a channel, rows from the top of `box`.
struct DiscSplat {
    ClipRect box;  // the pixels the discs cover, cut to the clip; empty when they cover none
    std::vector<std::uint8_t> rgba;
};

// The working memory of splat_discs, kept by the caller so that a frame allocates nothing.
struct SplatScratch {
    std::vector<float> layer;      // the premultiplied float layer
    std::vector<ClipRect> pixels;  // each disc's pixels, worked out once
};

// Composites shapes[begin, end) (each splat_eligible) in order into `out`, inside `clip` only.
void splat_discs(const std::vector<const Shape*>& shapes, size_t begin, size_t end, const ClipRect& clip,
                 DiscSplat& out, SplatScratch& scratch);

}  // namespace polyroll::render
