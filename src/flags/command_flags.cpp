// The flag handles over CLI11: see command_flags.h. The one file of the commands' flags that
// includes CLI11.
#include "flags/command_flags.h"

#include <cstdint>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

namespace polyroll::flags {

Flag& Flag::group(const std::string& name) {
    option_->group(name);
    return *this;
}

Flag& Flag::check(Range range) {
    option_->check(CLI::Range(range.min, range.max));
    return *this;
}

Flag& Flag::check(std::function<std::string(const std::string&)> problem) {
    // No description: help shows the flag's type once, as without the check.
    option_->check(CLI::Validator(std::move(problem), ""));
    return *this;
}

Flag& Flag::excludes(const Flag& other) {
    option_->excludes(other.option_);
    return *this;
}

Flag& Flag::needs(const Flag& other) {
    option_->needs(other.option_);
    return *this;
}

Flag& Flag::required() {
    option_->required();
    return *this;
}

Flag& Flag::delimiter(char separator) {
    option_->delimiter(separator);
    return *this;
}

std::size_t Flag::count() const { return option_ == nullptr ? 0 : option_->count(); }

std::string Flag::name() const { return option_ == nullptr ? std::string() : option_->get_name(); }

Command Command::add_subcommand(const std::string& name, const std::string& description) {
    return Command(*app_->add_subcommand(name, description));
}

CLI::App& Command::newest_subcommand() const { return *app_->get_subcommands({}).back(); }

void Command::footer(const std::string& text) { app_->footer(text); }

template <class T>
Flag Command::add_option(const std::string& name, T& value, const std::string& help) {
    return Flag(app_->add_option(name, value, help));
}

Flag Command::add_option_function(const std::string& name, const std::function<void(const std::string&)>& take,
                                  const std::string& help) {
    return Flag(app_->add_option_function<std::string>(name, take, help));
}

Flag Command::add_flag(const std::string& name, bool& value, const std::string& help) {
    return Flag(app_->add_flag(name, value, help));
}

// The value types the commands' flags have.
template Flag Command::add_option(const std::string&, int&, const std::string&);
template Flag Command::add_option(const std::string&, double&, const std::string&);
template Flag Command::add_option(const std::string&, std::uint64_t&, const std::string&);
template Flag Command::add_option(const std::string&, std::string&, const std::string&);
template Flag Command::add_option(const std::string&, std::vector<std::string>&, const std::string&);

}  // namespace polyroll::flags
