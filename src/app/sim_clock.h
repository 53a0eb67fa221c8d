// The clock that keeps the physics at its real rate while the window draws at its own: the
// simulated time the lanes should have reached, advanced by each frame's wall time (divided by the
// slow-motion factor). The lanes then take fixed tracker steps up to it within a wall-time budget;
// when the budget runs out the backlog is dropped (the simulation slows down, the UI does not
// freeze) and the clock reports that it is not keeping up.
#pragma once

namespace polyroll::app {

class SimClock {
public:
    // Slow motion: simulated time runs at 1/divisor of wall time (1 = real time).
    void set_slow_divisor(int divisor);
    int slow_divisor() const { return divisor_; }

    // A frame of wall time passed while playing: the target moves on (a stall counts as at most
    // kMaxFrameDtS, so a frozen window does not owe a burst of steps).
    void advance(double wall_dt_s);
    double target_s() const { return target_s_; }

    // After stepping: `reached_s` is where the slowest running lane got to; `budget_hit` says the
    // frame's physics budget ran out first, in which case the backlog is dropped.
    void frame_done(double wall_dt_s, double reached_s, bool budget_hit);

    // Back to time `t_s` (reset, a new scene, pausing): nothing owed, the rate window emptied.
    void restart(double t_s);

    // Simulated seconds per wall second over about the last kRateWindowS, and whether that kept up
    // with the chosen rate (no budget overrun in the window).
    double realtime_ratio() const { return ratio_; }
    bool keeping_up() const { return keeping_up_; }

private:
    int divisor_ = 1;
    double target_s_ = 0.0;
    double last_reached_s_ = 0.0;
    // The rate window.
    double window_wall_s_ = 0.0, window_sim_s_ = 0.0;
    bool window_overrun_ = false;
    double ratio_ = 0.0;
    bool keeping_up_ = true;
};

}  // namespace polyroll::app
