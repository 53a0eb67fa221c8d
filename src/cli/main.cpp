// polyroll: the headless tool. Runs scenes, renders them to frames, lists presets and measures speed;
// never opens a window. Only rendering creates a GL context (OSMesa, offscreen); a data run has none.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "cli/command_table.h"
#include "flags/parse_errors.h"
#include "sim/build_info.h"
#include "sim/errors.h"
#include "sim/message_text.h"

int main(int argc, char** argv) {
    using namespace polyroll;
    using namespace polyroll::cli;
    CLI::App app{"polyroll: hollow polygons partly filled with grains, rolling down an incline (2D, Box2D).\n"
                 "Units are SI (m, kg, s, m/s) and degrees."};
    app.require_subcommand(1);
    app.set_version_flag("--version", polyroll::version_text("polyroll"), "print the version, Box2D's and the build type");
    auto commands = add_all_commands(app);
    // `polyroll help run` is `polyroll run --help`.
    std::vector<std::string> args = flags::with_help_command(std::vector<std::string>(argv, argv + argc), app);
    // Bare `polyroll` asks what the tool does; nothing was mistyped, so it gets `polyroll --help` and exit
    // 0, as cargo, docker, kubectl and pip answer their bare names. A flag with no command is still
    // refused (exit 2): that is a mistake to name.
    if (args.size() == 1) args.push_back("--help");
    std::vector<const char*> arg_pointers;
    arg_pointers.reserve(args.size());
    for (const std::string& a : args) arg_pointers.push_back(a.c_str());
    try {
        app.parse(static_cast<int>(arg_pointers.size()), arg_pointers.data());
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // One line naming the bad flag or value, in the program's words; usage is one --help away.
        const std::vector<std::string> given(args.begin() + 1, args.end());
        fmt::print(stderr, "polyroll: {}\n", polyroll::printable_line(flags::parse_error_text(e, app, given)));
        return kExitBadInput;
    }
    try {
        for (auto& [sub, action] : commands) {
            if (!sub->parsed()) continue;
            // A folder flag given as "" (an unset shell variable) would write into the current folder.
            for (const char* name : {"--out", "--from", "--merge"}) {
                const CLI::Option* o = sub->get_option_no_throw(name);
                if (o == nullptr || o->count() == 0) continue;
                for (const std::string& v : o->results())
                    if (v.empty())
                        throw polyroll::InputError(fmt::format("{} '': an empty folder name (allowed: a folder path, "
                                                               "e.g. {} runs/mine)", name, name));
            }
            return action();
        }
    } catch (const polyroll::InputError& e) {
        fmt::print(stderr, "polyroll: {}\n", polyroll::printable_line(e.what()));
        return kExitBadInput;
    } catch (const std::exception& e) {
        fmt::print(stderr, "polyroll: error: {}\n", polyroll::printable_line(e.what()));
        return kExitFailure;
    }
    return kExitFailure;
}
