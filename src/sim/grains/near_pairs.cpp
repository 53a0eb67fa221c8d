// Grain contacts for near pairs only: see near_pairs.h.
#include "sim/grains/near_pairs.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "sim/grains/world_builder.h"

namespace polyroll {

namespace {

// A grain's fixture carries its index + 1 in its user data once mapped (0: not a grain).
size_t tag_of(b2Fixture* f) { return f->GetUserData().pointer; }

// Box2D gives the contact manager only as const, but the world (and so the manager) is never
// const: adding and destroying contacts through it is what the world's own step does.
b2ContactManager& contact_manager(b2World& world) { return const_cast<b2ContactManager&>(world.GetContactManager()); }

struct AllProxies {
    const b2BroadPhase* broad_phase;
    std::vector<b2FixtureProxy*> found;
    bool QueryCallback(int32 proxy_id) {
        found.push_back(static_cast<b2FixtureProxy*>(broad_phase->GetUserData(proxy_id)));
        return true;
    }
};

// A coordinate's cell, in cells: a grain flung far away, or a diverging run's infinity or NaN (the
// run's divergence check reports it), gets a cell far from the pile's instead of overflowing an int.
int cell_index(float cells) {
    constexpr float kFar = 1.0e9f;
    const float c = std::floor(cells);
    if (!(c > -kFar)) return -static_cast<int>(kFar);
    if (c > kFar) return static_cast<int>(kFar);
    return static_cast<int>(c);
}

}  // namespace

bool NearPairs::ShouldCollide(b2Fixture* a, b2Fixture* b) {
    const size_t ta = tag_of(a), tb = tag_of(b);
    if (ta == 0 || tb == 0) return b2ContactFilter::ShouldCollide(a, b);
    return within(ta - 1, tb - 1, a->GetBody()->GetPosition(), b->GetBody()->GetPosition(), reach_units_);
}

void NearPairs::map_proxies(SimWorld& w) {
    const size_t n = w.grains.size();
    proxies_.assign(n, nullptr);
    radius_.assign(n, 0.0f);
    for (size_t i = 0; i < n; ++i) {
        b2Fixture* f = w.grains[i]->GetFixtureList();
        f->GetUserData().pointer = i + 1;
        radius_[i] = f->GetShape()->m_radius;
    }
    const b2BroadPhase& bp = w.world->GetContactManager().m_broadPhase;
    AllProxies all{&bp, {}};
    const float huge = 0.5f * b2_maxFloat;
    bp.Query(&all, b2AABB{{-huge, -huge}, {huge, huge}});
    for (b2FixtureProxy* p : all.found) {
        const size_t tag = tag_of(p->fixture);
        if (tag != 0) proxies_[tag - 1] = p;
    }
    cell_units_ = 2.0f * *std::max_element(radius_.begin(), radius_.end()) + reach_units_;
}

void NearPairs::prune_contacts(SimWorld& w) {
    const size_t n = w.grains.size();
    b2ContactManager& cm = contact_manager(*w.world);
    kept_pairs_.clear();
    kept_start_.assign(n + 1, 0);
    for (b2Contact* c = w.world->GetContactList(); c != nullptr;) {
        b2Contact* next = c->GetNext();
        const size_t ta = tag_of(c->GetFixtureA()), tb = tag_of(c->GetFixtureB());
        if (ta != 0 && tb != 0) {
            const size_t i = std::min(ta, tb) - 1, j = std::max(ta, tb) - 1;
            if (!c->IsTouching() && !within(i, j, position_[i], position_[j], keep_units_)) {
                cm.Destroy(c);
            } else {
                kept_pairs_.push_back((static_cast<uint64_t>(i) << 32) | j);
                ++kept_start_[i + 1];
            }
        }
        c = next;
    }
    // The kept pairs as lists by their lower grain (a counting sort): a grain has a few.
    for (size_t i = 0; i < n; ++i) kept_start_[i + 1] += kept_start_[i];
    kept_other_.resize(kept_pairs_.size());
    cursor_.assign(kept_start_.begin(), kept_start_.end() - 1);
    for (const uint64_t key : kept_pairs_) kept_other_[cursor_[key >> 32]++] = static_cast<int>(key & 0xFFFFFFFFu);
}

void NearPairs::sort_into_cells(size_t n) {
    cell_x_.resize(n);
    cell_y_.resize(n);
    int x_min = std::numeric_limits<int>::max(), y_min = x_min;
    int x_max = std::numeric_limits<int>::min(), y_max = x_max;
    for (size_t i = 0; i < n; ++i) {
        cell_x_[i] = cell_index(position_[i].x / cell_units_);
        cell_y_[i] = cell_index(position_[i].y / cell_units_);
        x_min = std::min(x_min, cell_x_[i]);
        x_max = std::max(x_max, cell_x_[i]);
        y_min = std::min(y_min, cell_y_[i]);
        y_max = std::max(y_max, cell_y_[i]);
    }
    // A pile fills its cells' box about half; a grain flown far away would make the box huge.
    const int64_t w = int64_t{x_max} - x_min + 1, h = int64_t{y_max} - y_min + 1;
    dense_ = w * h <= 8 * static_cast<int64_t>(n) + 4096;
    if (dense_) {
        grid_x0_ = x_min;
        grid_y0_ = y_min;
        grid_w_ = static_cast<int>(w);
        grid_h_ = static_cast<int>(h);
        buckets_ = static_cast<size_t>(w * h);
    } else {
        buckets_ = std::bit_ceil(2 * n);
    }
    cell_start_.assign(buckets_ + 1, 0);
    for (size_t i = 0; i < n; ++i) ++cell_start_[cell_of(cell_x_[i], cell_y_[i]) + 1];
    for (size_t k = 0; k < buckets_; ++k) cell_start_[k + 1] += cell_start_[k];
    cursor_.assign(cell_start_.begin(), cell_start_.end() - 1);
    order_.resize(n);
    for (size_t i = 0; i < n; ++i) order_[cursor_[cell_of(cell_x_[i], cell_y_[i])]++] = static_cast<int>(i);
}

void NearPairs::before_step(SimWorld& w) {
    const size_t n = w.grains.size();
    if (n < 2) return;
    if (proxies_.size() != n) map_proxies(w);
    b2ContactManager& cm = contact_manager(*w.world);

    position_.resize(n);
    for (size_t i = 0; i < n; ++i) position_[i] = w.grains[i]->GetPosition();

    // Far grain contacts go (they do not touch, so they hold no impulse); the rest are remembered.
    prune_contacts(w);

    // Near pairs, by grain, then by the cells around it row by row (the order the contacts are made
    // in), each cell's grains in ascending order.
    sort_into_cells(n);
    auto consider = [&](size_t i, size_t j) {
        if (j <= i || !within(i, j, position_[i], position_[j], reach_units_) || has_contact(i, j)) return;
        cm.AddPair(proxies_[i], proxies_[j]);
    };
    for (size_t i = 0; i < n; ++i) {
        for (int dy = -1; dy <= 1; ++dy) {
            const int cy = cell_y_[i] + dy;
            if (dense_) {
                // A row's three cells sit side by side in the grid: one run of grains.
                if (cy < grid_y0_ || cy - grid_y0_ >= grid_h_) continue;
                const int x_lo = std::max(cell_x_[i] - 1, grid_x0_), x_hi = std::min(cell_x_[i] + 1, grid_x0_ + grid_w_ - 1);
                const int end = cell_start_[cell_of(x_hi, cy) + 1];
                for (int s = cell_start_[cell_of(x_lo, cy)]; s < end; ++s) consider(i, static_cast<size_t>(order_[s]));
                continue;
            }
            for (int dx = -1; dx <= 1; ++dx) {
                const int cx = cell_x_[i] + dx;
                const size_t k = cell_of(cx, cy);
                for (int s = cell_start_[k]; s < cell_start_[k + 1]; ++s) {
                    const auto j = static_cast<size_t>(order_[s]);
                    if (cell_x_[j] == cx && cell_y_[j] == cy) consider(i, j);  // a bucket holds other cells too
                }
            }
        }
    }
}

}  // namespace polyroll
