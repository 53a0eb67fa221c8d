// The subcommand table: see command_table.h.
#include "cli/command_table.h"

namespace polyroll::cli {

std::vector<std::pair<CLI::App*, Action>> add_all_commands(CLI::App& app) {
    std::vector<std::pair<CLI::App*, Action>> commands;
    Command root(app);
    auto add = [&](Action (*adder)(Command&)) {
        Action a = adder(root);
        commands.emplace_back(&root.newest_subcommand(), std::move(a));
    };
    add(add_run_command);
    add(add_presets_command);
    add(add_render_command);
    add(add_compare_command);
    add(add_sweep_command);
    add(add_figures_command);
    add(add_tradeoff_command);
    add(add_validate_command);
    add(add_calibrate_command);
    add(add_bench_command);
    return commands;
}

}  // namespace polyroll::cli
