// Every polyroll subcommand registered on one app: shared by main() and the command-line fuzzer, so
// the fuzzer parses exactly the command line people use.
#pragma once

#include <utility>
#include <vector>

#include "cli/commands.h"

namespace polyroll::cli {

// Registers each subcommand on `app`; returns each with the action to run once it is parsed.
std::vector<std::pair<CLI::App*, Action>> add_all_commands(CLI::App& app);

}  // namespace polyroll::cli
