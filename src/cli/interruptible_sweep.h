// Runs a sweep plan from a command (sweep, validate) so that Ctrl-C or SIGTERM stops it after the runs
// in flight, with every table consistent and the same command resuming; a second Ctrl-C stops at once.
#pragma once

#include <string>

#include "sweep/sweep_plan.h"
#include "sweep/sweep_runner.h"

namespace polyroll::cli {

inline constexpr int kExitInterrupted = 130;  // 128 + SIGINT, as shells report an interrupted command

// `command` names the command in the message printed at the first Ctrl-C ("polyroll sweep").
// The previous signal handlers are back in place however the sweep ends. Inside an InterruptScope the
// scope's handlers and stop flag are used instead.

sweep::SweepReport run_sweep_interruptibly(const sweep::SweepPlan& plan, const sweep::SweepOptions& options,
                                           const std::string& command);

// Holds the Ctrl-C handlers for a command that runs several sweeps (calibrate): a Ctrl-C between two
// sweeps is not lost, and every later sweep stops at once. Not nested.
class InterruptScope {
public:
    explicit InterruptScope(const std::string& command);
    ~InterruptScope();
    InterruptScope(const InterruptScope&) = delete;
    InterruptScope& operator=(const InterruptScope&) = delete;
    bool interrupted() const;

private:
    void (*old_int_)(int);
    void (*old_term_)(int);
};

}  // namespace polyroll::cli
