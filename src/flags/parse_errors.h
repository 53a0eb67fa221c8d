// Command-line parse errors in polyroll's own words. CLI11 reports a bad flag as "Could not convert:
// --fill = abc" or "At Most 1 required but received 2"; a user should read what was wrong, what is
// allowed, and which command's --help to read, the way every other input error reads.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace polyroll::flags {

// `polyroll help` and `polyroll help CMD` as `polyroll --help` and `polyroll CMD --help`; a CMD that
// is not one of app's commands is left for the parser to refuse as an unknown command ("did you
// mean"). Any other argument list is returned unchanged. args[0] is the program name.
std::vector<std::string> with_help_command(std::vector<std::string> args, const CLI::App& app);

// One line for a parse error of `app` (already parsed as far as it got), ending with where to read
// more: "(see polyroll run --help)". args are the arguments given, without the program name.
std::string parse_error_text(const CLI::ParseError& e, const CLI::App& app, const std::vector<std::string>& args);

// One line for a parse error of a program without commands (polyroll-sandbox), in the same words as
// polyroll's: what was wrong and what is allowed, ending "(see PROGRAM --help)". `allowed` names what a
// flag takes where its type alone does not say it, e.g. {"--ui-scale", "0.75 to 2.5"}.
std::string flag_error_text(const CLI::ParseError& e, const CLI::App& app, const std::string& program,
                            const std::map<std::string, std::string>& allowed = {});

// The closest of `names` to `typed` when close enough to be a typing slip ("rnu" -> "run"), else "".
std::string closest_name(const std::string& typed, const std::vector<std::string>& names);

}  // namespace polyroll::flags
