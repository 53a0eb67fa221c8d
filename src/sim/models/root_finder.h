// The one root finder of the rigid polygon's models: where along a stretch an event happens, given a
// bracket of it. Every event is a value that is positive before it and turns non-positive where it
// happens (an angle reaching a face, a rate reaching zero, a vertex's height, the normal force, the
// friction to spare), so one routine serves the rolling polygon's impacts and turning points, where
// its normal force fails, and the free body's contact and flight events.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace polyroll::models {

// The first tau in (lo, hi] where f turns non-positive, given f(lo) = f_lo > 0 >= f(hi) = f_hi (lo
// itself if f_lo <= 0): false position with the Illinois halving (a handful of evaluations for a
// smooth f where halving takes thirty; a jump, as where a contact's force changes form, still
// converges). Ends once the bracket is under tol_s, or under a few roundings of tau with tol_s = 0,
// and returns its upper end, where f <= 0 holds. Adds the evaluations of f to `evaluations`.
template <class F>
double first_root(F f, double lo, double f_lo, double hi, double f_hi, double tol_s, long& evaluations) {
    if (f_lo <= 0.0) return lo;
    constexpr double kRoundings = 4.0 * std::numeric_limits<double>::epsilon();
    int side = 0;
    for (int i = 0; i < 100; ++i) {
        if (hi - lo <= std::max(tol_s, kRoundings * std::max(std::fabs(lo), std::fabs(hi)))) break;
        double m = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        if (!(m > lo && m < hi)) m = 0.5 * (lo + hi);
        if (!(m > lo && m < hi)) break;  // lo and hi are neighbouring numbers
        const double fm = f(m);
        ++evaluations;
        if (fm == 0.0) return m;  // on the root: nothing left to narrow
        if (fm < 0.0) {
            hi = m;
            f_hi = fm;
            if (side < 0) f_lo *= 0.5;
            side = -1;
        } else {
            lo = m;
            f_lo = fm;
            if (side > 0) f_hi *= 0.5;
            side = 1;
        }
    }
    return hi;
}

template <class F>
double first_root(F f, double lo, double f_lo, double hi, double f_hi, double tol_s) {
    long unused = 0;
    return first_root(f, lo, f_lo, hi, f_hi, tol_s, unused);
}

}  // namespace polyroll::models
