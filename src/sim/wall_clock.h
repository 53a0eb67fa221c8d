// Wall-clock time, for what a run or a benchmark reports of its own speed (never for the physics).
#pragma once

#include <chrono>

namespace polyroll {

using WallClock = std::chrono::steady_clock;

// Seconds of wall-clock time since `start`.
inline double seconds_since(WallClock::time_point start) {
    return std::chrono::duration<double>(WallClock::now() - start).count();
}

}  // namespace polyroll
