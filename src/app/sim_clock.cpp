// The fixed-step clock with its real-time cap: see sim_clock.h.
#include "app/sim_clock.h"

#include <algorithm>

#include "app/sandbox_settings.h"

namespace polyroll::app {

void SimClock::set_slow_divisor(int divisor) { divisor_ = std::max(1, divisor); }

void SimClock::advance(double wall_dt_s) {
    const double dt = std::clamp(wall_dt_s, 0.0, kMaxFrameDtS);
    target_s_ += dt / divisor_;
}

void SimClock::frame_done(double wall_dt_s, double reached_s, bool budget_hit) {
    // Dropping the backlog is what slows the simulation instead of letting the debt grow without end.
    if (budget_hit) target_s_ = reached_s;
    window_wall_s_ += std::max(0.0, wall_dt_s);
    window_sim_s_ += std::max(0.0, reached_s - last_reached_s_);
    window_overrun_ = window_overrun_ || budget_hit;
    last_reached_s_ = reached_s;
    if (window_wall_s_ >= kRateWindowS) {
        ratio_ = window_sim_s_ / window_wall_s_;
        keeping_up_ = !window_overrun_ && ratio_ >= kKeepingUpShare / divisor_;
        window_wall_s_ = window_sim_s_ = 0.0;
        window_overrun_ = false;
    } else if (budget_hit) {
        keeping_up_ = false;  // say so at once, not a second later
    }
}

void SimClock::restart(double t_s) {
    target_s_ = last_reached_s_ = t_s;
    window_wall_s_ = window_sim_s_ = 0.0;
    window_overrun_ = false;
    ratio_ = 0.0;
    keeping_up_ = true;
}

}  // namespace polyroll::app
