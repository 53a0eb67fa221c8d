// Readable numbers for axes and scales: see ticks.h.
#include "render/ticks.h"

#include <algorithm>
#include <cmath>

namespace polyroll::render {

double nice_ceil(double x) {
    if (!(x > 0.0)) return 1.0;
    const double p = std::pow(10.0, std::floor(std::log10(x)));
    // The tolerance keeps an x that is already nice (up to rounding) from going up a step.
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= x * (1.0 - 1e-9)) return m * p;
    return 10.0 * p;
}

double nice_ceil(double x, double floor) {
    const double v = std::max(x, floor);  // NaN stays NaN here
    return v > 0.0 && std::isfinite(v) ? nice_ceil(v) : floor;
}

double round_up_nice(double x, double intervals) {
    if (!(x > 0.0)) return 0.0;
    const double step = nice_ceil(x / intervals);
    return std::ceil(x / step - 1e-9) * step;
}

double growing_time_axis_s(double t_s) { return std::max(1.0, round_up_nice(std::max(t_s, 1.0), 8.0)); }

AxisRange growing_value_axis(double lo, double hi, double hi_floor, double lo_floor) {
    return {lo < 0.0 ? -nice_ceil(-lo, lo_floor) : 0.0, nice_ceil(hi, hi_floor)};
}

AxisTicks axis_ticks(double lo, double hi, double intervals) {
    AxisTicks t;
    t.step = nice_ceil((hi - lo) / intervals);
    // + 0.0 turns the -0 that ceil gives for lo = 0 into 0, which a label would print as "-0".
    t.first = std::ceil(lo / t.step - 1e-9) * t.step + 0.0;
    // An integer count: a floating-point counter would gather rounding error tick by tick, and never
    // end for a step of 0 or NaN.
    const double last = std::floor((hi + 1e-9 - t.first) / t.step);
    t.count = std::isfinite(last) ? static_cast<int>(std::clamp(last, -1.0, kMaxTicks - 1.0)) + 1 : 0;
    return t;
}

}  // namespace polyroll::render
