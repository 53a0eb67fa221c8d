// When frames are taken: frame k shows the first simulation step at or after simulated time
// k / (fps x slow), so frames follow simulated time whatever the physics step, and --slow K gives K
// times as many frames per simulated second. Integer steps keep the schedule exact over long runs.
#pragma once

#include <cmath>

#include "sim/sample_clock.h"

namespace polyroll::render {

struct FrameSchedule {
    double fps = 30.0;     // frames per second of video
    int slow = 1;          // slow-motion factor
    double step_hz = 1000; // simulation steps per simulated second
    double hold_s = 1.0;   // seconds of video the final state is held for

    double frames_per_sim_s() const { return fps * slow; }
    // The step whose state frame k (0-based) shows.
    long step_for_frame(long k) const { return first_step_at(k, step_hz, frames_per_sim_s()); }
    // How many frames a run that ends at `end_step` gives, before the hold.
    long run_frames(long end_step) const {
        return static_cast<long>(std::floor((static_cast<double>(end_step) + 1e-9) * frames_per_sim_s() / step_hz)) + 1;
    }
    long hold_frames() const { return static_cast<long>(std::lround(hold_s * fps)); }
    long total_frames(long end_step) const { return run_frames(end_step) + hold_frames(); }
};

}  // namespace polyroll::render
