// Sequential deposition of discs: see grain_deposition.h.
#include "sim/grains/grain_deposition.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

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

// The polygon's edges with their inward normals (counter-clockwise polygon).
std::vector<Edge> inward_edges(const std::vector<Vec2>& poly) {
    const size_t n = poly.size();
    std::vector<Edge> edges(n);
    for (size_t i = 0; i < n; ++i) {
        const Vec2 e = poly[(i + 1) % n] - poly[i];
        const double len = geom::length(e);
        edges[i].normal = {-e.y / len, e.x / len};  // inward for a counter-clockwise polygon
        edges[i].offset = geom::dot(edges[i].normal, poly[i]);
    }
    return edges;
}

// The lowest of the places offered to one grain. Equally low places are mirror images in a symmetric
// pile: choosing by position (or by rounding noise) would lean every pile the same way, so one is
// drawn, each as likely.
class LowestPlace {
public:
    LowestPlace(Vec2 up, double tie, const std::function<double()>& tie_break)
        : up_(up), tie_(tie), tie_break_(tie_break) {}

    // Offers `p`; `fits(p)` is asked only of places no higher than the best so far.
    template <class Fits>
    void consider(Vec2 p, const Fits& fits) {
        const double h = geom::dot(p, up_);
        if (h > best_h_ + tie_ || !fits(p)) return;
        const bool tied = h >= best_h_ - tie_;
        if (tied) {
            ++ties_;
            if (tie_break_() * ties_ >= 1.0) return;
        } else {
            ties_ = 1;
        }
        best_h_ = tied ? std::min(best_h_, h) : h;
        best_ = p;
    }
    bool found() const { return std::isfinite(best_h_); }
    double height() const { return best_h_; }
    Vec2 place() const { return best_; }

private:
    Vec2 up_;
    double tie_;
    const std::function<double()>& tie_break_;
    double best_h_ = std::numeric_limits<double>::infinity();
    Vec2 best_{};
    int ties_ = 0;  // places found so far at the best height
};

// The grains placed so far, with the neighbour grid and the grains near the top where new ones can rest.
class Pile {
public:
    Pile(const std::vector<Vec2>& poly, Vec2 up, double max_radius)
        : edges_(inward_edges(poly)),
          up_(up),
          max_radius_(max_radius),
          gap_(1e-3 * max_radius),
          eps_(1e-9 * max_radius),
          grid_(poly, 2.0 * (max_radius + gap_)) {}

    double gap() const { return gap_; }
    const std::vector<Disc>& discs() const { return discs_; }
    std::vector<Disc> take() { return std::move(discs_); }

    // Offers every resting place of a grain of radius `rr` (its gap included), in a fixed order:
    // against two walls, against a wall and a grain, against two grains.
    void offer_places(double rr, LowestPlace& lowest) const {
        const auto fits = [&](Vec2 p) { return this->fits(p, rr); };
        offer_corners(rr, lowest, fits);
        offer_wall_and_grain(rr, lowest, fits);
        offer_two_grains(rr, lowest, fits);
    }

    // Places a grain of radius `rr - gap` at `p`, `height` up; grains well below the newest one are
    // buried: they no longer offer resting places.
    void add(Vec2 p, double rr, double height) {
        const int index = static_cast<int>(discs_.size());
        discs_.push_back({p, rr - gap_});
        grid_.insert(index, p);
        active_.push_back(index);
        last_height_ = std::max(last_height_, height);
        const double buried_below = last_height_ - 6.0 * max_radius_;
        std::erase_if(active_, [&](int i) { return geom::dot(discs_[static_cast<size_t>(i)].centre, up_) < buried_below; });
    }

private:
    bool fits(Vec2 p, double rr) const {
        for (const Edge& e : edges_)
            if (geom::dot(e.normal, p) - e.offset < rr - eps_) return false;
        bool ok = true;
        grid_.near(p, rr + max_radius_ + gap_, [&](int j) {
            const Disc& d = discs_[static_cast<size_t>(j)];
            if (ok && geom::length(p - d.centre) < rr + d.radius - eps_) ok = false;
        });
        return ok;
    }

    // Against two adjacent walls: the corner, offset inwards by the radius.
    template <class Fits>
    void offer_corners(double rr, LowestPlace& lowest, const Fits& fits) const {
        const size_t n = edges_.size();
        for (size_t i = 0; i < n; ++i) {
            const Edge& a = edges_[i];
            const Edge& b = edges_[(i + 1) % n];
            const double det = a.normal.x * b.normal.y - a.normal.y * b.normal.x;
            if (std::fabs(det) < 1e-12) continue;
            const double ca = a.offset + rr, cb = b.offset + rr;
            lowest.consider({(ca * b.normal.y - cb * a.normal.y) / det, (a.normal.x * cb - b.normal.x * ca) / det}, fits);
        }
    }

    template <class Fits>
    void offer_wall_and_grain(double rr, LowestPlace& lowest, const Fits& fits) const {
        for (int j : active_) {
            const Disc& d = discs_[static_cast<size_t>(j)];
            const double reach = rr + d.radius;
            for (const Edge& e : edges_) {
                const double s = e.offset + rr - geom::dot(e.normal, d.centre);
                if (std::fabs(s) > reach) continue;
                const Vec2 foot = d.centre + s * e.normal;
                const Vec2 along = {e.normal.y, -e.normal.x};
                const double half = std::sqrt(reach * reach - s * s);
                lowest.consider(foot + half * along, fits);
                lowest.consider(foot - half * along, fits);
            }
        }
    }

    template <class Fits>
    void offer_two_grains(double rr, LowestPlace& lowest, const Fits& fits) const {
        for (int j : active_) {
            const Disc& a = discs_[static_cast<size_t>(j)];
            const double ra = rr + a.radius;
            grid_.near(a.centre, 2.0 * (rr + max_radius_), [&](int k) {
                if (k <= j) return;
                const Disc& b = discs_[static_cast<size_t>(k)];
                const double rb = rr + b.radius;
                const Vec2 ab = b.centre - a.centre;
                const double dist = geom::length(ab);
                if (dist > ra + rb || dist < std::fabs(ra - rb) || dist == 0.0) return;
                const double x = (dist * dist + ra * ra - rb * rb) / (2.0 * dist);
                const double y = std::sqrt(std::max(0.0, ra * ra - x * x));
                const Vec2 u = (1.0 / dist) * ab, v = {-u.y, u.x};
                lowest.consider(a.centre + x * u + y * v, fits);
                lowest.consider(a.centre + x * u - y * v, fits);
            });
        }
    }

    std::vector<Edge> edges_;
    Vec2 up_;
    double max_radius_, gap_, eps_;
    Grid grid_;
    std::vector<Disc> discs_;
    std::vector<int> active_;  // grains near the top of the pile, where new grains can rest
    double last_height_ = -std::numeric_limits<double>::infinity();
};

}  // namespace

std::vector<Disc> deposit_grains(const std::vector<Vec2>& poly, Vec2 up, double surface_level,
                                 const std::function<double()>& next_radius, double max_radius,
                                 std::size_t max_count, const std::function<double()>& tie_break) {
    const double tie = 1e-9 * max_radius;  // heights closer than this are equal
    Pile pile(poly, up, max_radius);
    while (pile.discs().size() < max_count) {
        const double rr = next_radius() + pile.gap();  // each grain is placed as if `gap` larger
        LowestPlace lowest(up, tie, tie_break);
        pile.offer_places(rr, lowest);
        if (!lowest.found()) break;  // nowhere left inside
        if (lowest.height() > surface_level && !pile.discs().empty()) break;
        pile.add(lowest.place(), rr, lowest.height());
        if (lowest.height() > surface_level) break;  // the single grain of a fill too small for one
    }
    return pile.take();
}

}  // namespace polyroll
