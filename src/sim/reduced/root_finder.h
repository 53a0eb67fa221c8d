// The one root finder of the rigid polygon's models: where along a stretch an event happens, given a
// bracket of it. Every event is a value that is positive before it and turns non-positive where it
// happens (an angle reaching a face, a rate reaching zero, a vertex's height, the normal force, the
// friction to spare), so one routine serves the rolling polygon's impacts and turning points, where
// its normal force fails, and the free body's contact and flight events.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace polyroll::models {

// An event value with its time derivative, where the dense output gives both in one pass (a series'
// value and rate from one Horner sweep): the root finder then takes Newton steps inside the bracket.
struct Slope {
    double value = 0.0;
    double derivative = 0.0;
};

namespace detail {
inline Slope as_slope(double v) { return {v, 0.0}; }
inline Slope as_slope(Slope s) { return s; }
}  // namespace detail

// The first tau in (lo, hi] where f turns non-positive, given f(lo) = f_lo > 0 >= f(hi) = f_hi (lo
// itself if f_lo <= 0): false position with the Illinois halving (a handful of evaluations for a
// smooth f where halving takes thirty; a jump, as where a contact's force changes form, still
// converges). An f returning a Slope adds Newton steps from the newest point wherever they land
// inside the bracket (two or three evaluations for a series' crossing where false position takes six
// or seven); each is pushed at least the end tolerance on, so a converged Newton step also closes the
// bracket. Ends once the bracket is under tol_s, or under a few roundings of tau with tol_s = 0, and
// returns its upper end, where f <= 0 holds. Adds the evaluations of f to `evaluations`.
template <class F>
double first_root(F f, double lo, double f_lo, double hi, double f_hi, double tol_s, long& evaluations) {
    if (f_lo <= 0.0) return lo;
    constexpr bool kNewton = std::is_same_v<std::invoke_result_t<F, double>, Slope>;
    constexpr double kRoundings = 4.0 * std::numeric_limits<double>::epsilon();
    int side = 0;
    double x_new = 0.0;
    Slope at_new{};
    bool have_new = false;
    for (int i = 0; i < 100; ++i) {
        const double close = std::max(tol_s, kRoundings * std::max(std::fabs(lo), std::fabs(hi)));
        if (hi - lo <= close) break;
        double m = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        bool newton = false;
        if (kNewton && have_new && at_new.derivative != 0.0) {
            const double step = -at_new.value / at_new.derivative;
            const double pushed = x_new + std::copysign(std::max(std::fabs(step), 0.5 * close), step);
            if (pushed > lo && pushed < hi) {
                m = pushed;
                newton = true;
            }
        }
        if (!(m > lo && m < hi)) m = 0.5 * (lo + hi);
        if (!(m > lo && m < hi)) break;  // lo and hi are neighbouring numbers
        const Slope sm = detail::as_slope(f(m));
        const double fm = sm.value;
        ++evaluations;
        if (fm == 0.0) return m;  // on the root: nothing left to narrow
        x_new = m;
        at_new = sm;
        have_new = true;
        if (newton) side = 0;  // the Illinois halving is for runs of false-position steps
        if (fm < 0.0) {
            hi = m;
            f_hi = fm;
            if (side < 0) f_lo *= 0.5;
            side = newton ? 0 : -1;
        } else {
            lo = m;
            f_lo = fm;
            if (side > 0) f_hi *= 0.5;
            side = newton ? 0 : 1;
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
