// The sweep's progress line on stderr: runs done of the total, failures, time spent and time left.
// On a terminal it redraws one line a few times a second; into a log it prints a line every 10%.
#pragma once

#include <chrono>
#include <cstdio>
#include <mutex>
#include <optional>
#include <string>

namespace polyroll::sweep {

// What the time left is worked out from: the runs' estimated costs (run_cost.h) and the measured
// times of those finished.
struct CostTally {
    std::size_t runs_left = 0;
    double estimated_left_s = 0.0;  // the runs not finished yet (those in flight included), by estimate
    double estimated_done_s = 0.0;  // the runs finished, by estimate
    double measured_done_s = 0.0;   // the same runs, each its own wall time
    int jobs = 1;                   // runs at a time
};

// The time left: the estimated cost of the runs left, scaled by how the finished runs' measured times
// compare with their estimates, spread over the runs that can still run at once. A sweep's runs can
// differ in cost a thousandfold (an empty shell, a full one of rice), so an average over the runs
// finished says little about the ones left. Without estimates, this session's average pace
// (`elapsed_s` over `done` runs); nothing before a run has finished.
std::optional<double> time_left_s(const CostTally& t, double elapsed_s, std::size_t done);

class Progress {
public:
    // `total` runs in this session, `already` done before it (a resumed sweep); `estimated_s` the
    // session's runs by their estimates (0: none), run `jobs` at a time.
    Progress(std::size_t total, std::size_t already, bool quiet, std::FILE* out = stderr, double estimated_s = 0.0,
             int jobs = 1);
    // A run finished: its estimate and the wall time it took.
    void run_done(bool failed, double estimated_s = 0.0, double measured_s = 0.0);
    void finish();  // the final line
    std::size_t done() const { return done_; }
    std::size_t failed() const { return failed_; }
    double elapsed_s() const;

    // "1:02:03" or "4:05"
    static std::string clock_text(double seconds);

private:
    std::string line() const;
    std::size_t total_, already_;
    std::size_t done_ = 0, failed_ = 0;
    CostTally cost_;
    bool quiet_, tty_;
    std::FILE* out_;
    std::chrono::steady_clock::time_point start_, last_draw_;
    int last_decile_ = 0;
    std::mutex mutex_;
};

}  // namespace polyroll::sweep
