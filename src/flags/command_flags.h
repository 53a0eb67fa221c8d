// A command's flags as the commands declare them: thin handles over CLI11's App and Option, so that
// a file which only declares flags does not include CLI11. CLI11 is header-only and large: a file
// that includes it costs about 5.5 CPU-seconds more to compile (g++ -O3) and 10 more in clang-tidy,
// paid by every file that saw it (measured in docs/testing.md). Only command_flags.cpp, the parse
// errors' wording (parse_errors.cpp) and the programs that build and parse an app (cli/main.cpp,
// app/sandbox_main.cpp, the command-line fuzzer) include it.
//
// The handles keep CLI11's names and meaning (add_option, group, check, excludes, ...): whatever
// CLI11's documentation says of them holds here. add_option is defined for the value types the
// commands use (explicit instantiations in command_flags.cpp; another type is a link error there).
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace polyroll::flags {

// A whole-number range, both ends allowed: CLI::Range(min, max) on an integer flag.
struct Range {
    Range(int min_value, int max_value) : min(min_value), max(max_value) {}
    int min, max;
};

// One flag or positional of a command (CLI::Option). A default-made Flag is no flag: count() is 0.
class Flag {
public:
    Flag() = default;
    explicit Flag(CLI::Option* option) : option_(option) {}

    Flag& group(const std::string& name);
    Flag& check(Range range);
    // `problem` returns "" for a good value, else what is wrong with it (shown as the error).
    Flag& check(std::function<std::string(const std::string&)> problem);
    Flag& excludes(const Flag& other);
    Flag& needs(const Flag& other);
    Flag& required();
    Flag& delimiter(char separator);

    std::size_t count() const;  // times given on the command line
    std::string name() const;   // the flag's long name, e.g. "--fill"

private:
    CLI::Option* option_ = nullptr;
};

// A command (CLI::App) on which flags and subcommands are declared. It does not own the app.
class Command {
public:
    explicit Command(CLI::App& app) : app_(&app) {}

    Command add_subcommand(const std::string& name, const std::string& description);
    void footer(const std::string& text);

    template <class T>
    Flag add_option(const std::string& name, T& value, const std::string& help);
    // A flag whose text is passed to `take` when it is given.
    Flag add_option_function(const std::string& name, const std::function<void(const std::string&)>& take,
                             const std::string& help);
    Flag add_flag(const std::string& name, bool& value, const std::string& help);

    // The subcommand added last (for the program that parses the app and runs what was chosen).
    CLI::App& newest_subcommand() const;

private:
    CLI::App* app_;
};

}  // namespace polyroll::flags
