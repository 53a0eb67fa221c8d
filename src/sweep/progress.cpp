// The progress line: see progress.h.
#include "sweep/progress.h"

#include <algorithm>
#include <cmath>

#include <unistd.h>

#include <fmt/core.h>

namespace polyroll::sweep {

std::optional<double> time_left_s(const CostTally& t, double elapsed_s, std::size_t done) {
    if (t.runs_left == 0) return 0.0;
    if (done == 0) return std::nullopt;
    const double at_once = static_cast<double>(std::min<std::size_t>(static_cast<std::size_t>(std::max(1, t.jobs)),
                                                                     t.runs_left));
    if (t.estimated_done_s > 0.0 && t.estimated_left_s > 0.0)
        return t.estimated_left_s * (t.measured_done_s / t.estimated_done_s) / at_once;
    // Runs finished earlier in the folder cost nothing now: this session's pace only.
    return elapsed_s / static_cast<double>(done) * static_cast<double>(t.runs_left);
}

Progress::Progress(std::size_t total, std::size_t already, bool quiet, std::FILE* out, double estimated_s, int jobs)
    : total_(total), already_(already), quiet_(quiet), tty_(::isatty(::fileno(out)) != 0), out_(out),
      start_(std::chrono::steady_clock::now()), last_draw_(start_) {
    cost_.runs_left = total;
    cost_.estimated_left_s = estimated_s;
    cost_.jobs = jobs;
}

double Progress::elapsed_s() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string Progress::clock_text(double seconds) {
    const long s = std::lround(std::max(0.0, seconds));
    if (s >= 3600) return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
    return fmt::format("{}:{:02}", s / 60, s % 60);
}

std::string Progress::line() const {
    const std::size_t all = total_ + already_, now = done_ + already_;
    constexpr int width = 24;
    const int filled = all ? static_cast<int>(width * static_cast<double>(now) / static_cast<double>(all)) : width;
    const double t = elapsed_s();
    const std::optional<double> left_s = time_left_s(cost_, t, done_);
    const std::string left = left_s ? clock_text(*left_s) : std::string("?");
    return fmt::format("[{}{}] {}/{} runs, {} failed, {} elapsed, {} left", std::string(filled, '#'),
                       std::string(width - filled, '.'), now, all, failed_, clock_text(t), left);
}

void Progress::run_done(bool failed, double estimated_s, double measured_s) {
    std::lock_guard<std::mutex> g(mutex_);
    ++done_;
    if (failed) ++failed_;
    cost_.runs_left = total_ - std::min(done_, total_);
    cost_.estimated_left_s = std::max(0.0, cost_.estimated_left_s - estimated_s);
    cost_.estimated_done_s += estimated_s;
    cost_.measured_done_s += measured_s;
    if (quiet_) return;
    const auto now = std::chrono::steady_clock::now();
    if (tty_) {
        if (now - last_draw_ > std::chrono::milliseconds(200) || done_ == total_) {
            fmt::print(out_, "\r{}\033[K", line());
            std::fflush(out_);
            last_draw_ = now;
        }
    } else {
        const int decile = total_ ? static_cast<int>(10 * done_ / total_) : 10;
        if (decile > last_decile_) {
            fmt::print(out_, "{}\n", line());
            std::fflush(out_);
            last_decile_ = decile;
        }
    }
}

void Progress::finish() {
    std::lock_guard<std::mutex> g(mutex_);
    if (quiet_) return;
    if (tty_) fmt::print(out_, "\r{}\033[K\n", line());
    std::fflush(out_);
}

}  // namespace polyroll::sweep
