// Small discs composited on the CPU: see disc_splat.h.
#include "render/disc_splat.h"

#include <algorithm>
#include <cmath>

#include "render/changed_regions.h"
#include "render/whole_pixels.h"

namespace polyroll::render {

bool splat_eligible(const Shape& s) {
    return s.kind == ShapeKind::capsule && s.a.x == s.b.x && s.a.y == s.b.y && s.radius <= kSplatMaxRadiusPx;
}

namespace {

// The pixels whose centres lie closer to the disc's centre than its radius and the half-pixel fringe
// (the only ones its coverage reaches), rows from the top.
ClipRect covered_pixels(const Shape& s) {
    if (!(std::isfinite(s.a.x) && std::isfinite(s.a.y) && std::isfinite(s.radius))) return {};
    // Far outside any frame: kept within a range an int holds, the clip cuts it anyway.
    if (std::abs(s.a.x) > 1e6f || std::abs(s.a.y) > 1e6f) return {};
    // Pixel p's centre is p + 0.5: from the first p past centre - reach - 0.5 to the last short of
    // centre + reach - 0.5.
    const float reach = s.radius + 0.5f;
    const int x0 = floor_px(s.a.x - reach - 0.5f) + 1, x1 = ceil_px(s.a.x + reach - 0.5f);
    const int y0 = floor_px(s.a.y - reach - 0.5f) + 1, y1 = ceil_px(s.a.y + reach - 0.5f);
    return {x0, y0, x1 - x0, y1 - y0};
}

ClipRect bounding(const ClipRect& a, const ClipRect& b) {
    if (a.empty()) return b;
    const int x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
    const int x1 = std::max(a.x + a.width, b.x + b.width), y1 = std::max(a.y + a.height, b.y + b.height);
    return {x0, y0, x1 - x0, y1 - y0};
}

}  // namespace

void splat_discs(const std::vector<const Shape*>& shapes, size_t begin, size_t end, const ClipRect& clip,
                 DiscSplat& out, SplatScratch& scratch) {
    ClipRect box;
    scratch.pixels.clear();
    for (size_t i = begin; i < end; ++i) {
        scratch.pixels.push_back(covered_pixels(*shapes[i]));
        box = bounding(box, scratch.pixels.back());
    }
    out.box = intersection(box, clip);
    out.rgba.clear();
    if (out.box.empty()) return;
    const ClipRect& b = out.box;
    std::vector<float>& layer = scratch.layer;
    layer.assign(static_cast<size_t>(b.width) * static_cast<size_t>(b.height) * 4, 0.0f);
    for (size_t i = begin; i < end; ++i) {
        const Shape& s = *shapes[i];
        const ClipRect c = intersection(scratch.pixels[i - begin], b);
        if (c.empty()) continue;
        const float r = s.radius, w = s.outline_px;
        const float reach2 = (r + 0.5f) * (r + 0.5f);
        for (int y = c.y; y < c.y + c.height; ++y) {
            const float dy = static_cast<float>(y) + 0.5f - s.a.y;
            float* row = layer.data() + (static_cast<size_t>(y - b.y) * static_cast<size_t>(b.width)) * 4;
            for (int x = c.x; x < c.x + c.width; ++x) {
                const float dx = static_cast<float>(x) + 0.5f - s.a.x;
                // disc_colour in gl_renderer.cpp, term for term.
                const float d2 = dx * dx + dy * dy;
                if (d2 >= reach2) continue;  // no coverage: the formula below would give 0, without a root
                const float d = std::sqrt(d2) - r;
                const float cover = std::clamp(0.5f - d, 0.0f, 1.0f);
                if (cover <= 0.0f) continue;
                Rgba col = s.fill;
                if (w > 0.0f) {
                    const float t = std::clamp(-(d + w) + 0.5f, 0.0f, 1.0f);
                    col = {s.outline.r + (s.fill.r - s.outline.r) * t, s.outline.g + (s.fill.g - s.outline.g) * t,
                           s.outline.b + (s.fill.b - s.outline.b) * t, s.outline.a + (s.fill.a - s.outline.a) * t};
                }
                const float a = col.a * cover, keep = 1.0f - a;
                float* p = row + static_cast<size_t>(x - b.x) * 4;
                p[0] = col.r * a + p[0] * keep;
                p[1] = col.g * a + p[1] * keep;
                p[2] = col.b * a + p[2] * keep;
                p[3] = a + p[3] * keep;
            }
        }
    }
    out.rgba.resize(layer.size());
    std::transform(layer.begin(), layer.end(), out.rgba.begin(), [](float v) {
        // Rounded to the nearest level: the value is never negative here, where truncating v + 0.5 is
        // right, and std::lround is a library call on every channel of every pixel.
        return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);  // NOLINT(bugprone-incorrect-roundings)
    });
}

}  // namespace polyroll::render
