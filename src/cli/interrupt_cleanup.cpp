// Ctrl-C during a single run or render: see interrupt_cleanup.h.
#include "cli/interrupt_cleanup.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>

#include <unistd.h>

#include <fmt/core.h>

namespace polyroll::cli {

namespace {
// Set by the handler (all a handler may safely do); the watcher thread does the rest.
std::atomic<int> g_signal{0};

extern "C" void note_signal(int sig) { g_signal.store(sig); }
}  // namespace

CleanUpOnInterrupt::CleanUpOnInterrupt(std::string command, std::optional<std::filesystem::path> created)
    : command_(std::move(command)), created_(std::move(created)) {
    g_signal.store(0);
    old_int_ = std::signal(SIGINT, note_signal);
    old_term_ = std::signal(SIGTERM, note_signal);
    watcher_ = std::thread([this] { watch(); });
}

CleanUpOnInterrupt::~CleanUpOnInterrupt() {
    done_.store(true);
    watcher_.join();
    std::signal(SIGINT, old_int_);
    std::signal(SIGTERM, old_term_);
}

void CleanUpOnInterrupt::watch() {
    using namespace std::chrono_literals;
    while (!done_.load()) {
        if (const int sig = g_signal.load(); sig != 0) {
            std::error_code ec;
            if (created_) std::filesystem::remove_all(*created_, ec);
            // On a terminal the progress line is being redrawn in place: end it first.
            fmt::print(stderr, "{}{}: interrupted ({}); {}\n", ::isatty(STDERR_FILENO) ? "\n" : "", command_, sig == SIGINT ? "Ctrl-C" : "SIGTERM",
                       created_ ? fmt::format("the folder {} it made is removed, nothing half-written is left",
                                              created_->string())
                                : std::string("no files written"));
            std::fflush(stderr);
            std::_Exit(128 + sig);
        }
        std::this_thread::sleep_for(20ms);
    }
}

}  // namespace polyroll::cli
