// The sampling rule every record follows: sample (or frame) k is the state at the first step of the
// fixed-step grid at or after time k / rate, so records follow simulated time whatever the step.
#pragma once

#include <cmath>

namespace polyroll {

// The first step of a `step_hz` grid at or after time k / `rate_hz`. The 1e-9 keeps a time that falls
// on a step but for rounding (k * step_hz / rate_hz = 4.000000000000001) on that step.
inline long first_step_at(long k, double step_hz, double rate_hz) {
    return static_cast<long>(std::ceil(static_cast<double>(k) * step_hz / rate_hz - 1e-9));
}

}  // namespace polyroll
