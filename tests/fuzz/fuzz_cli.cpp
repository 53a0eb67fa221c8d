// libFuzzer target for the command line: the input is split into arguments at NUL bytes and parsed
// by the real subcommand table (nothing is run: no simulation, no files). Then the scene flags alone
// are parsed and resolved the way every scene-running command resolves them. A CLI::ParseError or an
// InputError is the expected refusal; any other exception, a crash or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/command_table.h"
#include "cli/scene_options.h"
#include "sim/errors.h"

namespace {

std::vector<std::string> split_arguments(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args{"polyroll"};
    std::string current;
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == 0) {
            args.push_back(current);
            current.clear();
        } else {
            current += static_cast<char>(data[i]);
        }
    }
    if (!current.empty()) args.push_back(current);
    return args;
}

std::vector<char*> argv_of(std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    return argv;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace polyroll;
    std::vector<std::string> args = split_arguments(data, size);
    // --scene names a file: keep the fuzzer off the file system (scene files have their own target).
    for (const auto& a : args)
        if (a.rfind("--scene", 0) == 0) return 0;
    {
        std::vector<char*> argv = argv_of(args);
        CLI::App app{"polyroll"};
        app.require_subcommand(1);
        auto commands = cli::add_all_commands(app);
        try {
            app.parse(static_cast<int>(args.size()), argv.data());
        } catch (const CLI::ParseError&) {
        }
    }
    {
        std::vector<char*> argv = argv_of(args);
        CLI::App app{"scene flags"};
        cli::SceneOptions scene;
        flags::Command command(app);
        scene.add_to(command);
        app.allow_extras();
        try {
            app.parse(static_cast<int>(args.size()), argv.data());
            (void)scene.resolve();
        } catch (const CLI::ParseError&) {
        } catch (const InputError&) {
        }
    }
    return 0;
}
