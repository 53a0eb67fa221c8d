// Grain-on-grain contacts kept for the pairs that touch or nearly touch, instead of every pair whose
// fattened boxes overlap.
//
// Why: Box2D 2.4.1 keeps a contact for every pair of fixtures whose boxes, fattened by a fixed
// 0.1-unit margin (1 mm at the engine's unit: half a BB disc), overlap. In a big pile that is 10-15
// contacts a disc of which fewer than 2 touch, and every step walks all of them: evaluates each
// (Collide), walks them while building islands and while checking new pairs (AddPair). A contact
// whose circles do not touch carries nothing into the solver (no manifold point, so no impulse to
// warm-start), so a pile whose far pairs have no contact at all steps the same motion.
//
// How, before each engine step: every grain-on-grain contact that does not touch and whose circles
// are further apart than `keep_units` is destroyed, and every pair of grains closer than
// `reach_units` (found on a grid of cells a disc across) is given a contact if it has none. The
// engine's own pair search still runs; a contact filter refuses the grain pairs it finds further
// apart than `reach_units`. Box2D finds new pairs at the end of a step, at the positions the next
// step's contacts are evaluated at, and this runs at those same positions (nothing moves between
// the two but ShiftOrigin, which moves everything alike), so every pair that touches when a step
// begins has its contact. The order of the contact list changes, and with it the solver's order:
// rounding, grown through the pile's chaos, as the pile's frame does (moving_frame.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <box2d/box2d.h>

namespace polyroll {

struct SimWorld;

class NearPairs : public b2ContactFilter {
public:
    NearPairs(float reach_units, float keep_units) : reach_units_(reach_units), keep_units_(keep_units) {}

    // Box2D's own pair search: grain pairs further apart than the reach are refused.
    bool ShouldCollide(b2Fixture* a, b2Fixture* b) override;

    // Before each engine step: far contacts destroyed, near pairs given one.
    void before_step(SimWorld& w);

    // Whether the last pass sorted the grains on a dense grid (false: hashed buckets), for tests.
    bool dense_grid() const { return dense_; }

private:
    void map_proxies(SimWorld& w);
    // Far grain contacts destroyed; the kept pairs listed by their lower grain (has_contact).
    void prune_contacts(SimWorld& w);
    // The grains sorted into cells at least one reach across: a dense grid over the pile's cells, or
    // hashed buckets when a grain has flown so far that the dense grid would be too big.
    void sort_into_cells(size_t n);
    // The cell's list in cell_start_; on the dense grid, buckets_ for a cell outside it.
    size_t cell_of(int cx, int cy) const {
        if (dense_) {
            if (cx < grid_x0_ || cy < grid_y0_ || cx - grid_x0_ >= grid_w_ || cy - grid_y0_ >= grid_h_) return buckets_;
            return static_cast<size_t>(cy - grid_y0_) * static_cast<size_t>(grid_w_) + static_cast<size_t>(cx - grid_x0_);
        }
        const auto h = static_cast<uint32_t>(cx) * 73856093u ^ static_cast<uint32_t>(cy) * 19349663u;
        return static_cast<size_t>(h) & (buckets_ - 1);
    }
    bool has_contact(size_t i, size_t j) const {  // i < j
        for (int k = kept_start_[i]; k < kept_start_[i + 1]; ++k) {
            if (static_cast<size_t>(kept_other_[k]) == j) return true;
        }
        return false;
    }
    bool within(size_t i, size_t j, b2Vec2 pi, b2Vec2 pj, float gap) const {
        const float reach = radius_[i] + radius_[j] + gap;
        return b2DistanceSquared(pi, pj) <= reach * reach;
    }

    float reach_units_;
    float keep_units_;
    float cell_units_ = 0.0f;
    std::vector<b2FixtureProxy*> proxies_;  // by grain index, found once after the pour
    std::vector<float> radius_;             // by grain index
    // Scratch, kept between steps to avoid allocating: the grains' positions and cells; the pairs
    // that have a contact, as a list of the higher grain's index per lower grain (kept_start_ and
    // kept_other_, from the pairs kept_pairs_ collects); the grains in cell order (cell_start_ and
    // order_; within a cell, by ascending index, so contacts are made in the same order either way).
    std::vector<b2Vec2> position_;
    std::vector<uint64_t> kept_pairs_;
    std::vector<int> kept_start_, kept_other_;
    std::vector<int> cell_x_, cell_y_, cell_start_, order_, cursor_;
    bool dense_ = true;  // cells on a dense grid (else hashed into buckets)
    int grid_x0_ = 0, grid_y0_ = 0, grid_w_ = 0, grid_h_ = 0;
    size_t buckets_ = 0;
};

}  // namespace polyroll
