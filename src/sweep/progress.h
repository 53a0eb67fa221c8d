// The sweep's progress line on stderr: runs done of the total, failures, time spent and time left.
// On a terminal it redraws one line a few times a second; into a log it prints a line every 10%.
#pragma once

#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace polyroll::sweep {

class Progress {
public:
    // `total` runs in this session, `already` done before it (a resumed sweep).
    Progress(std::size_t total, std::size_t already, bool quiet, std::FILE* out = stderr);
    void run_done(bool failed);
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
    bool quiet_, tty_;
    std::FILE* out_;
    std::chrono::steady_clock::time_point start_, last_draw_;
    int last_decile_ = 0;
    std::mutex mutex_;
};

}  // namespace polyroll::sweep
