// Ctrl-C for the commands that run sweeps: see interruptible_sweep.h.
#include "cli/interruptible_sweep.h"

#include <atomic>
#include <csignal>

#include <unistd.h>

namespace polyroll::cli {
namespace {

std::atomic<bool> g_stop{false};
// Built before the handlers are installed: a signal handler may only call async-signal-safe
// functions (write), not format text.
std::string g_message;

extern "C" void on_signal(int sig) {
    if (g_stop.exchange(true)) {  // the second Ctrl-C stops at once; the tables stay consistent
        std::signal(sig, SIG_DFL);
        std::raise(sig);
        return;
    }
    [[maybe_unused]] auto n = ::write(2, g_message.data(), g_message.size());
}

// Installs the handlers for its lifetime.
class SignalGuard {
public:
    SignalGuard() : old_int_(std::signal(SIGINT, on_signal)), old_term_(std::signal(SIGTERM, on_signal)) {}
    ~SignalGuard() {
        std::signal(SIGINT, old_int_);
        std::signal(SIGTERM, old_term_);
    }
    SignalGuard(const SignalGuard&) = delete;
    SignalGuard& operator=(const SignalGuard&) = delete;

private:
    void (*old_int_)(int);
    void (*old_term_)(int);
};

bool g_scoped = false;  // an InterruptScope holds the handlers

std::string stopping_message(const std::string& command) {
    return "\n" + command + ": stopping after the runs in flight (Ctrl-C again to stop now; the same command resumes)\n";
}

}  // namespace

InterruptScope::InterruptScope(const std::string& command) {
    g_message = stopping_message(command);
    g_stop = false;
    g_scoped = true;
    old_int_ = std::signal(SIGINT, on_signal);
    old_term_ = std::signal(SIGTERM, on_signal);
}

InterruptScope::~InterruptScope() {
    std::signal(SIGINT, old_int_);
    std::signal(SIGTERM, old_term_);
    g_scoped = false;
}

bool InterruptScope::interrupted() const { return g_stop; }

sweep::SweepReport run_sweep_interruptibly(const sweep::SweepPlan& plan, const sweep::SweepOptions& options,
                                           const std::string& command) {
    if (g_scoped) return sweep::run_sweep(plan, options, &g_stop);
    g_message = stopping_message(command);
    g_stop = false;
    const SignalGuard guard;
    return sweep::run_sweep(plan, options, &g_stop);
}

}  // namespace polyroll::cli
