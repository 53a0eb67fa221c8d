// The polyroll subcommands. Each registers its flags on the app and returns the action to run
// after parsing; an action returns the process exit code.
#pragma once

#include <functional>

#include "flags/command_flags.h"

namespace polyroll::cli {

// The commands declare their flags through the handles of flags/command_flags.h (not CLI11's own
// header: that header says why).
using flags::Command;
using flags::Flag;
using flags::Range;

// Exit codes, the same for every command.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;    // could not write results, or an internal error
inline constexpr int kExitBadInput = 2;   // a bad flag, scene file, preset or output folder
inline constexpr int kExitDiverged = 3;   // the run was numerically unsound; its files say where

using Action = std::function<int()>;

Action add_run_command(Command& app);
Action add_presets_command(Command& app);
Action add_bench_command(Command& app);
Action add_compare_command(Command& app);
Action add_render_command(Command& app);
Action add_sweep_command(Command& app);
Action add_figures_command(Command& app);
Action add_tradeoff_command(Command& app);
Action add_validate_command(Command& app);
Action add_calibrate_command(Command& app);

}  // namespace polyroll::cli
