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

// Axes that grow with the data in readable steps, so they do not twitch every frame: the frames'
// plot when the run's length is not known in advance, and the sandbox's live plots.
// Time, from 0: at least 1 s, in steps of about an eighth of its length (11.4 s -> 12 s, not 20 s).
double growing_time_axis_s(double t_s);
// A value axis holding 0 and [lo, hi]: each end rounded out to a nice number, at least `hi_floor`
// above and `lo_floor` below 0 when there are negative values.
struct AxisRange {
    double lo = 0.0, hi = 1.0;
};
AxisRange growing_value_axis(double lo, double hi, double hi_floor, double lo_floor);
// The speed plots' floors (frames and window): 0.1 m/s up; 0.01 m/s down once the lid rocks back.
inline constexpr double kSpeedAxisFloor_m_s = 0.1, kSpeedAxisFloorBelow_m_s = 0.01;

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
