// How far a long run has got, and whether to stop it: see run_progress.h.
#include "sim/run_progress.h"

#include <utility>

namespace polyroll {

namespace {
thread_local RunProgress t_hook;
thread_local RunStopCheck t_stop;
}  // namespace

ScopedRunProgress::ScopedRunProgress(RunProgress hook) : previous_(std::exchange(t_hook, std::move(hook))) {}

ScopedRunProgress::~ScopedRunProgress() { t_hook = std::move(previous_); }

void report_run_progress(double time_s, double distance_m) {
    if (t_hook) t_hook(time_s, distance_m);
}

ScopedRunStop::ScopedRunStop(RunStopCheck check) : previous_(std::exchange(t_stop, std::move(check))) {}

ScopedRunStop::~ScopedRunStop() { t_stop = std::move(previous_); }

bool run_stop_requested() { return t_stop && t_stop(); }

bool run_stop_hooked() { return static_cast<bool>(t_stop); }

}  // namespace polyroll
