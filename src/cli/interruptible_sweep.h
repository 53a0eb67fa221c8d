// Runs a sweep plan from a command (sweep, validate) so that Ctrl-C or SIGTERM stops it after the runs
// in flight, with every table consistent and the same command resuming; a second Ctrl-C stops at once.
#pragma once

#include <string>

#include "sweep/sweep_plan.h"
#include "sweep/sweep_runner.h"

namespace polyroll::cli {

inline constexpr int kExitInterrupted = 130;  // 128 + SIGINT, as shells report an interrupted command

// `command` names the command in the message printed at the first Ctrl-C ("polyroll sweep").
// The previous signal handlers are back in place however the sweep ends.
sweep::SweepReport run_sweep_interruptibly(const sweep::SweepPlan& plan, const sweep::SweepOptions& options,
                                           const std::string& command);

}  // namespace polyroll::cli
