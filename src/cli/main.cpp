// polyroll: the headless tool. Runs scenes, renders them to frames, lists presets and measures speed;
// never opens a window. Only rendering creates a GL context (OSMesa, offscreen); a data run has none.
#include <cstdio>
#include <exception>

#include <fmt/format.h>

#include "cli/commands.h"
#include "sim/errors.h"

int main(int argc, char** argv) {
    using namespace polyroll::cli;
    CLI::App app{"polyroll: hollow polygons partly filled with grains, rolling down an incline (2D, Box2D).\n"
                 "Units are SI (m, kg, s, m/s) and degrees."};
    app.require_subcommand(1);
    std::vector<std::pair<CLI::App*, Action>> commands;
    auto add = [&](Action (*adder)(CLI::App&)) {
        Action a = adder(app);
        commands.emplace_back(app.get_subcommands({}).back(), std::move(a));
    };
    add(add_run_command);
    add(add_presets_command);
    add(add_render_command);
    add(add_compare_command);
    add(add_sweep_command);
    add(add_figures_command);
    add(add_tradeoff_command);
    add(add_bench_command);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // One line naming the bad flag or value; usage is one --help away.
        fmt::print(stderr, "polyroll: {} (see polyroll --help)\n", e.what());
        return kExitBadInput;
    }
    try {
        for (auto& [sub, action] : commands)
            if (sub->parsed()) return action();
    } catch (const polyroll::InputError& e) {
        fmt::print(stderr, "polyroll: {}\n", e.what());
        return kExitBadInput;
    } catch (const std::exception& e) {
        fmt::print(stderr, "polyroll: error: {}\n", e.what());
        return kExitFailure;
    }
    return kExitFailure;
}
