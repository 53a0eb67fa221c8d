// Grain contacts for near pairs only: see near_pairs.h.
#include "sim/grains/near_pairs.h"

#include <algorithm>
#include <bit>
#include <cmath>

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

uint64_t pair_key(size_t i, size_t j) {
    if (i > j) std::swap(i, j);
    return (static_cast<uint64_t>(i) << 32) | static_cast<uint64_t>(j);
}

size_t slot_of(uint64_t key, size_t mask) { return static_cast<size_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & mask; }

}  // namespace

bool NearPairs::ShouldCollide(b2Fixture* a, b2Fixture* b) {
    const size_t ta = tag_of(a), tb = tag_of(b);
    if (ta == 0 || tb == 0) return b2ContactFilter::ShouldCollide(a, b);
    return within(ta - 1, tb - 1, a->GetBody()->GetPosition(), b->GetBody()->GetPosition(), reach_units_);
}

bool NearPairs::within(size_t i, size_t j, b2Vec2 pi, b2Vec2 pj, float gap) const {
    const float reach = radius_[i] + radius_[j] + gap;
    return b2DistanceSquared(pi, pj) <= reach * reach;
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

void NearPairs::before_step(SimWorld& w) {
    const size_t n = w.grains.size();
    if (n < 2) return;
    if (proxies_.size() != n) map_proxies(w);
    b2ContactManager& cm = contact_manager(*w.world);

    position_.resize(n);
    for (size_t i = 0; i < n; ++i) position_[i] = w.grains[i]->GetPosition();

    // Far grain contacts go (they do not touch, so they hold no impulse); the rest are remembered.
    const size_t set_size = std::bit_ceil(4 * static_cast<size_t>(w.world->GetContactCount()) + 16);
    const size_t set_mask = set_size - 1;
    pair_set_.assign(set_size, kEmpty);
    for (b2Contact* c = w.world->GetContactList(); c != nullptr;) {
        b2Contact* next = c->GetNext();
        const size_t ta = tag_of(c->GetFixtureA()), tb = tag_of(c->GetFixtureB());
        if (ta != 0 && tb != 0) {
            const size_t i = ta - 1, j = tb - 1;
            if (!c->IsTouching() && !within(i, j, position_[i], position_[j], keep_units_)) {
                cm.Destroy(c);
            } else {
                const uint64_t key = pair_key(i, j);
                size_t s = slot_of(key, set_mask);
                while (pair_set_[s] != kEmpty) s = (s + 1) & set_mask;
                pair_set_[s] = key;
            }
        }
        c = next;
    }
    auto has_contact = [&](size_t i, size_t j) {
        const uint64_t key = pair_key(i, j);
        for (size_t s = slot_of(key, set_mask); pair_set_[s] != kEmpty; s = (s + 1) & set_mask) {
            if (pair_set_[s] == key) return true;
        }
        return false;
    };

    // Near pairs, found on a grid of cells at least one reach across, hashed into buckets.
    const size_t buckets = std::bit_ceil(2 * n);
    cell_x_.resize(n);
    cell_y_.resize(n);
    order_.resize(n);
    bucket_start_.assign(buckets + 1, 0);
    auto bucket_of = [&](int cx, int cy) {
        const auto h = static_cast<uint32_t>(cx) * 73856093u ^ static_cast<uint32_t>(cy) * 19349663u;
        return static_cast<size_t>(h) & (buckets - 1);
    };
    for (size_t i = 0; i < n; ++i) {
        cell_x_[i] = static_cast<int>(std::floor(position_[i].x / cell_units_));
        cell_y_[i] = static_cast<int>(std::floor(position_[i].y / cell_units_));
        ++bucket_start_[bucket_of(cell_x_[i], cell_y_[i]) + 1];
    }
    for (size_t k = 0; k < buckets; ++k) bucket_start_[k + 1] += bucket_start_[k];
    cursor_.assign(bucket_start_.begin(), bucket_start_.end() - 1);
    for (size_t i = 0; i < n; ++i) order_[cursor_[bucket_of(cell_x_[i], cell_y_[i])]++] = static_cast<int>(i);
    for (size_t i = 0; i < n; ++i) {
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const int cx = cell_x_[i] + dx, cy = cell_y_[i] + dy;
                const size_t k = bucket_of(cx, cy);
                for (int s = bucket_start_[k]; s < bucket_start_[k + 1]; ++s) {
                    const auto j = static_cast<size_t>(order_[s]);
                    if (j <= i || cell_x_[j] != cx || cell_y_[j] != cy) continue;
                    if (!within(i, j, position_[i], position_[j], reach_units_) || has_contact(i, j)) continue;
                    cm.AddPair(proxies_[i], proxies_[j]);
                }
            }
        }
    }
}

}  // namespace polyroll
