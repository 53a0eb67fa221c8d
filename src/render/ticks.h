// Readable numbers for axes and scales: "nice" values (1, 2 or 5 times a power of ten), axis ends
// rounded up to a whole number of nice steps, and the ticks of an axis. One set of rules for the
// frames' speed plot, the ramp's length scale and the sandbox's live plots.
#pragma once

namespace polyroll::render {

// The smallest nice number at least `x`; 1 when x is not positive (or not a number).
double nice_ceil(double x);

// The same, at least `floor` (> 0); `floor` itself when x is not a finite number.
double nice_ceil(double x, double floor);

// `x` rounded up to a whole number of nice steps of about x / intervals, so an axis ends on a tick
// without wasting room: 1.225 -> 1.5 (fifths), 11.4 -> 12 (eighths). 0 when x is not positive.
double round_up_nice(double x, double intervals);

// An axis's ticks: first, first + step, ... (count of them), every tick inside [lo, hi].
struct AxisTicks {
    double first = 0.0;
    double step = 1.0;
    int count = 0;
    double at(int k) const { return first + k * step; }
};

// About `intervals` intervals over [lo, hi], a nice step apart; no ticks (count 0) for an axis that
// is not a finite range, and never more than kMaxTicks.
inline constexpr int kMaxTicks = 101;
AxisTicks axis_ticks(double lo, double hi, double intervals);

}  // namespace polyroll::render
