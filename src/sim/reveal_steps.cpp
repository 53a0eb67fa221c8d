// Revealing a whole run in tracker steps: see reveal_steps.h.
#include "sim/reveal_steps.h"

#include <algorithm>
#include <cmath>

namespace polyroll {

void reveal_up_to(Measurements& shown, const Measurements& whole, double time_s, bool finished) {
    const double t = time_s + 1e-12;
    while (shown.trajectory.size() < whole.trajectory.size() && whole.trajectory[shown.trajectory.size()].time_s <= t)
        shown.trajectory.push_back(whole.trajectory[shown.trajectory.size()]);
    while (shown.impacts.size() < whole.impacts.size() && whole.impacts[shown.impacts.size()].time_s <= t)
        shown.impacts.push_back(whole.impacts[shown.impacts.size()]);
    if (finished) {
        shown = whole;
    } else if (!shown.trajectory.empty()) {
        shown.distance_m = shown.trajectory.back().position_m;
        shown.end_time_s = time_s;
    }
}

long first_step_at_end(double end_time_s, double step_hz, long from_step) {
    const double end = end_time_s - 1e-12;
    if (!std::isfinite(end) || !(step_hz > 0.0)) return from_step;  // never for a validated scene
    long s = std::max(from_step, static_cast<long>(std::ceil(end * step_hz)));
    while (s > from_step && static_cast<double>(s - 1) / step_hz >= end) --s;
    while (static_cast<double>(s) / step_hz < end) ++s;
    return s;
}

}  // namespace polyroll
