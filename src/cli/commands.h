// The polyroll subcommands. Each registers its flags on the app and returns the action to run
// after parsing; an action returns the process exit code.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace polyroll::cli {

// Exit codes, the same for every command.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;    // could not write results, or an internal error
inline constexpr int kExitBadInput = 2;   // a bad flag, scene file, preset or output folder
inline constexpr int kExitDiverged = 3;   // the run was numerically unsound; its files say where

using Action = std::function<int()>;

Action add_run_command(CLI::App& app);
Action add_presets_command(CLI::App& app);
Action add_bench_command(CLI::App& app);
Action add_compare_command(CLI::App& app);
Action add_render_command(CLI::App& app);
Action add_sweep_command(CLI::App& app);
Action add_figures_command(CLI::App& app);
Action add_tradeoff_command(CLI::App& app);
Action add_validate_command(CLI::App& app);
Action add_calibrate_command(CLI::App& app);

}  // namespace polyroll::cli
