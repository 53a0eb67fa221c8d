// How far a long run has got: see run_progress.h.
#include "sim/run_progress.h"

#include <utility>

namespace polyroll {

namespace {
thread_local RunProgress t_hook;
}  // namespace

ScopedRunProgress::ScopedRunProgress(RunProgress hook) : previous_(std::exchange(t_hook, std::move(hook))) {}

ScopedRunProgress::~ScopedRunProgress() { t_hook = std::move(previous_); }

void report_run_progress(double time_s, double distance_m) {
    if (t_hook) t_hook(time_s, distance_m);
}

}  // namespace polyroll
