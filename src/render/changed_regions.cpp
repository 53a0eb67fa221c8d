// Where a draw list changed since the last frame: see changed_regions.h.
#include "render/changed_regions.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "render/disc_splat.h"
#include "render/whole_pixels.h"

namespace polyroll::render {

namespace {

// A float box grown to whole pixels and one pixel more: GL covers a pixel by its centre, and the
// shaders' quads already hold the one-pixel fringe (gl_renderer.cpp), so one more is a safe margin.
ClipRect around(float x0, float y0, float x1, float y1) {
    if (!(std::isfinite(x0) && std::isfinite(y0) && std::isfinite(x1) && std::isfinite(y1))) return {};
    // Far outside any frame: kept within a range an int holds, the frame cuts it anyway.
    const auto lo = [](float v) { return floor_px(std::clamp(v, -1e6f, 1e6f)) - 1; };
    const auto hi = [](float v) { return ceil_px(std::clamp(v, -1e6f, 1e6f)) + 1; };
    const int ix0 = lo(x0), iy0 = lo(y0);
    return {ix0, iy0, hi(x1) - ix0, hi(y1) - iy0};
}

ClipRect unite(const ClipRect& a, const ClipRect& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    const int x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
    const int x1 = std::max(a.x + a.width, b.x + b.width), y1 = std::max(a.y + a.height, b.y + b.height);
    return {x0, y0, x1 - x0, y1 - y0};
}

long long area(const ClipRect& r) { return r.empty() ? 0 : static_cast<long long>(r.width) * r.height; }

// Each place where the two sequences differ: both items' pixels (an item added or gone: its own).
template <typename T>
ClipRect differing(const std::vector<T>& before, const std::vector<T>& now) {
    ClipRect changed;
    for (std::size_t i = 0; i < std::max(before.size(), now.size()); ++i) {
        const bool was = i < before.size(), is = i < now.size();
        if (was && is && before[i] == now[i]) continue;
        if (was) changed = unite(changed, pixels_touched(before[i]));
        if (is) changed = unite(changed, pixels_touched(now[i]));
    }
    return changed;
}

// At most this many regions: past it they are merged into one around all.
constexpr std::size_t kMaxRegions = 6;
// Two regions become one where the rectangle around both is at most this much larger than the two.
constexpr double kMergeSlack = 1.25;

}  // namespace

ClipRect pixels_touched(const Triangle& t) {
    return around(std::min({t.a.x, t.b.x, t.c.x}), std::min({t.a.y, t.b.y, t.c.y}), std::max({t.a.x, t.b.x, t.c.x}),
                  std::max({t.a.y, t.b.y, t.c.y}));
}

ClipRect pixels_touched(const Shape& s) {
    if (s.kind == ShapeKind::box) return around(s.a.x - s.b.x - 1.0f, s.a.y - s.b.y - 1.0f, s.a.x + s.b.x + 1.0f, s.a.y + s.b.y + 1.0f);
    // A capsule's quad (or a disc's point sprite, 2 r + 2 wide) reaches r + 1 beyond its segment.
    const float e = s.radius + 1.0f;
    return around(std::min(s.a.x, s.b.x) - e, std::min(s.a.y, s.b.y) - e, std::max(s.a.x, s.b.x) + e,
                  std::max(s.a.y, s.b.y) + e);
}

ClipRect pixels_touched(const GlyphQuad& g) { return around(g.p0.x, g.p0.y, g.p1.x, g.p1.y); }

ClipRect intersection(const ClipRect& a, const ClipRect& b) {
    const int x0 = std::max(a.x, b.x), y0 = std::max(a.y, b.y);
    const int x1 = std::min(a.x + a.width, b.x + b.width), y1 = std::min(a.y + a.height, b.y + b.height);
    return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

bool overlap(const ClipRect& a, const ClipRect& b) { return !intersection(a, b).empty(); }

void add_region(std::vector<ClipRect>& regions, const ClipRect& r) {
    if (r.empty()) return;
    ClipRect merged = r;
    // Merging may make the new rectangle reach others: repeat until none is absorbed.
    for (bool absorbed = true; absorbed;) {
        absorbed = false;
        for (auto it = regions.begin(); it != regions.end(); ++it) {
            const ClipRect u = unite(*it, merged);
            if (static_cast<double>(area(u)) <= kMergeSlack * static_cast<double>(area(*it) + area(merged))) {
                merged = u;
                regions.erase(it);
                absorbed = true;
                break;
            }
        }
    }
    regions.push_back(merged);
    if (regions.size() > kMaxRegions) {
        ClipRect all;
        for (const ClipRect& x : regions) all = unite(all, x);
        regions = {all};
    }
}

std::vector<LayerPixels> pixels_of(const DrawList& list) {
    std::vector<LayerPixels> pixels(list.layers.size());
    for (size_t i = 0; i < list.layers.size(); ++i) {
        const Layer& layer = list.layers[i];
        LayerPixels& px = pixels[i];
        px.triangles.reserve(layer.triangles.size());
        for (const Triangle& t : layer.triangles) px.triangles.push_back(pixels_touched(t));
        px.shapes.reserve(layer.shapes.size());
        for (const Shape& s : layer.shapes) px.shapes.push_back(pixels_touched(s));
        px.glyphs.reserve(layer.glyphs.size());
        for (const GlyphQuad& g : layer.glyphs) px.glyphs.push_back(pixels_touched(g));
    }
    return pixels;
}

void hold_whole_discs(const DrawList& list, const std::vector<LayerPixels>& pixels, std::vector<ClipRect>& regions) {
    const ClipRect frame{0, 0, list.width_px, list.height_px};
    // The discs' pixels inside the frame, gathered once: a region may take several passes over them.
    std::vector<ClipRect> discs;
    for (size_t i = 0; i < list.layers.size(); ++i)
        for (size_t j = 0; j < list.layers[i].shapes.size(); ++j) {
            const Shape& s = list.layers[i].shapes[j];
            // A small disc is composited into an image cut to the region (disc_splat.h): nothing
            // of it is drawn outside.
            if (s.kind != ShapeKind::capsule || !(s.a == s.b) || splat_eligible(s)) continue;
            const ClipRect px = intersection(pixels[i].shapes[j], frame);
            if (!px.empty()) discs.push_back(px);
        }
    std::vector<ClipRect> grown;
    for (ClipRect r : regions) {
        // Each disc taken in may reach others: repeat until none is added.
        for (bool more = true; more;) {
            more = false;
            for (const ClipRect& px : discs) {
                if (!overlap(px, r) || intersection(px, r) == px) continue;
                r = unite(r, px);
                more = true;
            }
        }
        add_region(grown, r);
    }
    regions = std::move(grown);
}

std::optional<std::vector<ClipRect>> changed_regions(const DrawList& before, const DrawList& now) {
    if (before.width_px != now.width_px || before.height_px != now.height_px || !(before.background == now.background) ||
        before.bounds != now.bounds || before.atlas != now.atlas || before.layers.size() != now.layers.size())
        return std::nullopt;
    const ClipRect frame = now.bounds ? *now.bounds : ClipRect{0, 0, now.width_px, now.height_px};
    std::vector<ClipRect> regions;
    for (std::size_t i = 0; i < now.layers.size(); ++i) {
        const Layer &a = before.layers[i], &b = now.layers[i];
        if (a.clip != b.clip) return std::nullopt;
        ClipRect changed = differing(a.triangles, b.triangles);
        changed = unite(changed, differing(a.shapes, b.shapes));
        changed = unite(changed, differing(a.glyphs, b.glyphs));
        add_region(regions, intersection(b.clip ? intersection(*b.clip, frame) : frame, changed));
    }
    return regions;
}

}  // namespace polyroll::render
