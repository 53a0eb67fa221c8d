// The progress line: see progress.h.
#include "sweep/progress.h"

#include <cmath>

#include <unistd.h>

#include <fmt/format.h>

namespace polyroll::sweep {

Progress::Progress(std::size_t total, std::size_t already, bool quiet, std::FILE* out)
    : total_(total), already_(already), quiet_(quiet), tty_(::isatty(::fileno(out)) != 0), out_(out),
      start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

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
    // Time left from this session's pace (runs finished earlier cost nothing now).
    const std::string left = done_ > 0 ? clock_text(t / static_cast<double>(done_) * static_cast<double>(total_ - done_))
                                       : std::string("?");
    return fmt::format("[{}{}] {}/{} runs, {} failed, {} elapsed, {} left", std::string(filled, '#'),
                       std::string(width - filled, '.'), now, all, failed_, clock_text(t), left);
}

void Progress::run_done(bool failed) {
    std::lock_guard<std::mutex> g(mutex_);
    ++done_;
    if (failed) ++failed_;
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
