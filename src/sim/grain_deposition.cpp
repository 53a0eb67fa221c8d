// Sequential deposition of discs: see grain_deposition.h.
#include "sim/grain_deposition.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace polyroll {

using geom::Vec2;

namespace {

// A uniform grid over the polygon's bounding box, for neighbour queries.
class Grid {
public:
    Grid(const std::vector<Vec2>& poly, double cell) : cell_(cell) {
        Vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
        for (const Vec2& v : poly) {
            lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)};
            hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
        }
        origin_ = lo;
        nx_ = static_cast<int>((hi.x - lo.x) / cell) + 1;
        ny_ = static_cast<int>((hi.y - lo.y) / cell) + 1;
        cells_.resize(static_cast<size_t>(nx_) * static_cast<size_t>(ny_));
    }
    void insert(int index, Vec2 p) { cells_[key(cx(p.x), cy(p.y))].push_back(index); }
    // Calls f(index) for every disc in the cells within `reach` of p.
    template <class F>
    void near(Vec2 p, double reach, F&& f) const {
        const int x0 = cx(p.x - reach), x1 = cx(p.x + reach), y0 = cy(p.y - reach), y1 = cy(p.y + reach);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                for (int i : cells_[key(x, y)]) f(i);
    }

private:
    int cx(double x) const { return std::clamp(static_cast<int>(std::floor((x - origin_.x) / cell_)), 0, nx_ - 1); }
    int cy(double y) const { return std::clamp(static_cast<int>(std::floor((y - origin_.y) / cell_)), 0, ny_ - 1); }
    size_t key(int x, int y) const { return static_cast<size_t>(y) * static_cast<size_t>(nx_) + static_cast<size_t>(x); }

    double cell_;
    Vec2 origin_;
    int nx_ = 1, ny_ = 1;
    std::vector<std::vector<int>> cells_;
};

struct Edge {
    Vec2 normal;    // unit, pointing inside
    double offset;  // dot(normal, p) = offset on the edge's line
};

}  // namespace

std::vector<Disc> deposit_grains(const std::vector<Vec2>& poly, Vec2 up, double surface_level,
                                 const std::function<double()>& next_radius, double max_radius,
                                 std::size_t max_count, const std::function<double()>& tie_break) {
    std::vector<Disc> discs;
    const size_t n = poly.size();
    std::vector<Edge> edges(n);
    for (size_t i = 0; i < n; ++i) {
        const Vec2 e = poly[(i + 1) % n] - poly[i];
        const double len = geom::length(e);
        edges[i].normal = {-e.y / len, e.x / len};  // inward for a counter-clockwise polygon
        edges[i].offset = geom::dot(edges[i].normal, poly[i]);
    }
    const double tie = 1e-9 * max_radius;  // heights closer than this are equal
    const double gap = 1e-3 * max_radius;  // each grain is placed as if this much larger
    const double eps = 1e-9 * max_radius;
    Grid grid(poly, 2.0 * (max_radius + gap));
    std::vector<int> active;  // grains near the top of the pile, where new grains can rest
    double last_height = -std::numeric_limits<double>::infinity();

    while (discs.size() < max_count) {
        const double rr = next_radius() + gap;
        auto fits = [&](Vec2 p) {
            for (const Edge& e : edges)
                if (geom::dot(e.normal, p) - e.offset < rr - eps) return false;
            bool ok = true;
            grid.near(p, rr + max_radius + gap, [&](int j) {
                const Disc& d = discs[static_cast<size_t>(j)];
                if (ok && geom::length(p - d.centre) < rr + d.radius - eps) ok = false;
            });
            return ok;
        };
        double best_h = std::numeric_limits<double>::infinity();
        Vec2 best{};
        int ties = 0;  // places found so far at the best height
        auto consider = [&](Vec2 p) {
            const double h = geom::dot(p, up);
            if (h > best_h + tie || !fits(p)) return;
            const bool tied = h >= best_h - tie;
            // Equally low places are mirror images in a symmetric pile: choosing by position (or by
            // rounding noise) would lean every pile the same way, so one is drawn, each as likely.
            if (tied) {
                ++ties;
                if (tie_break() * ties >= 1.0) return;
            } else {
                ties = 1;
            }
            best_h = tied ? std::min(best_h, h) : h;
            best = p;
        };
        // Against two adjacent walls: the corner, offset inwards by the radius.
        for (size_t i = 0; i < n; ++i) {
            const Edge& a = edges[i];
            const Edge& b = edges[(i + 1) % n];
            const double det = a.normal.x * b.normal.y - a.normal.y * b.normal.x;
            if (std::fabs(det) < 1e-12) continue;
            const double ca = a.offset + rr, cb = b.offset + rr;
            consider({(ca * b.normal.y - cb * a.normal.y) / det, (a.normal.x * cb - b.normal.x * ca) / det});
        }
        // Against a wall and a grain.
        for (int j : active) {
            const Disc& d = discs[static_cast<size_t>(j)];
            const double reach = rr + d.radius;
            for (const Edge& e : edges) {
                const double s = e.offset + rr - geom::dot(e.normal, d.centre);
                if (std::fabs(s) > reach) continue;
                const Vec2 foot = d.centre + s * e.normal;
                const Vec2 along = {e.normal.y, -e.normal.x};
                const double half = std::sqrt(reach * reach - s * s);
                consider(foot + half * along);
                consider(foot - half * along);
            }
        }
        // Against two grains.
        for (int j : active) {
            const Disc& a = discs[static_cast<size_t>(j)];
            const double ra = rr + a.radius;
            grid.near(a.centre, 2.0 * (rr + max_radius), [&](int k) {
                if (k <= j) return;
                const Disc& b = discs[static_cast<size_t>(k)];
                const double rb = rr + b.radius;
                const Vec2 ab = b.centre - a.centre;
                const double dist = geom::length(ab);
                if (dist > ra + rb || dist < std::fabs(ra - rb) || dist == 0.0) return;
                const double x = (dist * dist + ra * ra - rb * rb) / (2.0 * dist);
                const double y = std::sqrt(std::max(0.0, ra * ra - x * x));
                const Vec2 u = (1.0 / dist) * ab, v = {-u.y, u.x};
                consider(a.centre + x * u + y * v);
                consider(a.centre + x * u - y * v);
            });
        }
        if (!std::isfinite(best_h)) break;  // nowhere left inside
        if (best_h > surface_level && !discs.empty()) break;
        const int index = static_cast<int>(discs.size());
        discs.push_back({best, rr - gap});
        grid.insert(index, best);
        active.push_back(index);
        // Grains well below the newest one are buried: they no longer offer resting places.
        last_height = std::max(last_height, best_h);
        const double buried_below = last_height - 6.0 * max_radius;
        std::erase_if(active, [&](int i) { return geom::dot(discs[static_cast<size_t>(i)].centre, up) < buried_below; });
        if (best_h > surface_level) break;  // the single grain of a fill too small for one
    }
    return discs;
}

}  // namespace polyroll
