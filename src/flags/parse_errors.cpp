// Parse errors in polyroll's words: see parse_errors.h.
#include "flags/parse_errors.h"

#include <algorithm>
#include <cstdlib>
#include <regex>

#include <fmt/core.h>

#include "sim/scene/scene_fields.h"

namespace polyroll::flags {

namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

// Edit distance (insertions, deletions, substitutions, and swapping two neighbours: "rnu" is one
// slip from "run").
std::size_t slips(const std::string& a, const std::string& b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

std::vector<std::string> command_names(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
    return names;
}

std::vector<std::string> flag_names(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::Option* o : app.get_options())
        for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
    return names;
}

using AllowedText = std::map<std::string, std::string>;

// What a flag of this CLI11 type name accepts, or what its scene field allows; `given` first (the
// program's own words for its flags).
std::string allowed_for(const std::string& flag, const std::string& type, const AllowedText& given = {}) {
    if (const auto it = given.find(flag); it != given.end()) return it->second;
    for (const SceneField& f : scene_fields())
        if (f.flag == flag) return field_allowed(f);
    if (type.find("UINT") != std::string::npos) return "a whole number from 0 to 2^64-1";
    if (type.find("INT") != std::string::npos) return "a whole number";
    if (type.find("FLOAT") != std::string::npos) return "a number, e.g. 0.25";
    return "";
}

std::string what_type(const std::string& type) {
    if (type.find("INT") != std::string::npos) return "a whole number";
    if (type.find("FLOAT") != std::string::npos) return "a number";
    return "a value of the right kind";
}

std::string unknown_command(const CLI::App& app, const std::vector<std::string>& args) {
    const std::vector<std::string> names = command_names(app);
    const auto first = std::find_if(args.begin(), args.end(), [](const std::string& a) { return !a.empty(); });
    if (first == args.end()) return fmt::format("a command is required (allowed: {})", joined(names));
    if (first->front() == '-')
        return fmt::format("a command is required before '{}' (allowed: {})", *first, joined(names));
    const std::string guess = closest_name(*first, names);
    if (!guess.empty()) return fmt::format("unknown command '{}'; did you mean '{}'?", *first, guess);
    return fmt::format("unknown command '{}' (allowed: {})", *first, joined(names));
}

std::string unknown_flag(const CLI::App& sub, const std::string& given) {
    const std::string name = given.substr(0, given.find('='));
    const std::string guess = closest_name(name, flag_names(sub));
    return guess.empty() ? fmt::format("unknown flag '{}'", name)
                         : fmt::format("unknown flag '{}'; did you mean '{}'?", name, guess);
}

// CLI11 lists the arguments it did not expect last first ("red --colour" for --colour red).
std::string unexpected(const CLI::App& sub, const std::string& list) {
    std::vector<std::string> items;
    for (std::size_t start = 0; start <= list.size();) {
        const std::size_t space = std::min(list.find(' ', start), list.size());
        if (space > start) items.push_back(list.substr(start, space - start));
        start = space + 1;
    }
    std::reverse(items.begin(), items.end());
    const auto flag = std::find_if(items.begin(), items.end(), [](const std::string& a) { return a.rfind("--", 0) == 0; });
    if (flag != items.end()) return unknown_flag(sub, *flag);
    if (items.empty()) return "unexpected arguments";
    // Lists are a polyroll command's matter (sweep takes them); a program without commands just takes one value.
    return fmt::format("unexpected value '{}' (each flag takes one value{})", items.front(),
                       sub.get_parent() ? "; lists are for polyroll sweep" : "");
}

std::string reworded(const std::string& what, const CLI::App& sub, const AllowedText& given = {}) {
    // CLI11 reports a missing required flag before a flag it does not know; the unknown one is the slip
    // to name (calibrate --param X said "--params is required").
    for (const std::string& a : sub.remaining())
        if (a.rfind("--", 0) == 0) return unknown_flag(sub, a);
    std::smatch m;
    static const std::regex convert(R"(^Could not convert: (\S+) = (.*)$)");
    static const std::regex at_most(R"(^(\S+): At Most (\d+) required but received (\d+)$)");
    static const std::regex missing(R"(^(\S+): (\d+) required (\S+) missing$)");
    static const std::regex extras(R"(^The following arguments? (?:was|were) not expected: (.*)$)");
    static const std::regex range(R"(^(\S+): Value (.*) not in range (.*) to (.*)$)");
    // A scene flag's text refused by the core's reading of typed text (cli/scene_options.cpp).
    static const std::regex field_text(R"(^(--\S+): (.*): ((?:not a|out of range).*)$)");
    if (std::regex_match(what, m, convert)) {
        const std::string name = m[1], value = m[2];
        const CLI::Option* o = sub.get_option_no_throw(name);
        const std::string type = o ? o->get_type_name() : "";
        const bool digits = !value.empty() && value.find_first_not_of("-+0123456789") == std::string::npos;
        const std::string allowed = allowed_for(name, type, given);
        return fmt::format("{} {}: {}{}", name, value, digits ? "out of range" : "not " + what_type(type),
                           allowed.empty() ? "" : " (allowed: " + allowed + ")");
    }
    if (std::regex_match(what, m, field_text)) return fmt::format("{} {}: {}", m[1].str(), m[2].str(), m[3].str());
    if (std::regex_match(what, m, at_most)) {
        if (m[2] == "1") return fmt::format("{} is given {} times (allowed: once)", m[1].str(), m[3].str());
        return fmt::format("{} takes at most {} values, got {}", m[1].str(), m[2].str(), m[3].str());
    }
    if (std::regex_match(what, m, missing)) {
        const std::string allowed = allowed_for(m[1], m[3], given);
        return fmt::format("{} needs a value{}", m[1].str(), allowed.empty() ? "" : " (allowed: " + allowed + ")");
    }
    if (std::regex_match(what, m, extras)) return unexpected(sub, m[1]);
    if (std::regex_match(what, m, range)) {
        // CLI11 checks a range before converting: "--jobs two" is not a number, not a number out of range.
        const std::string name = m[1], value = m[2];
        const CLI::Option* o = sub.get_option_no_throw(name);
        const std::string type = o ? o->get_type_name() : "";
        char* end = nullptr;
        const bool number =
            !value.empty() && (std::strtod(value.c_str(), &end), end == value.c_str() + value.size());
        static const std::regex whole(R"([-+]?\d+)");
        if (!number || (type.find("INT") != std::string::npos && !std::regex_match(value, whole)))
            return fmt::format("{} {}: not {} (allowed: {} to {})", name, value, what_type(type), m[3].str(),
                               m[4].str());
        return fmt::format("{} {} is out of range (allowed: {} to {})", name, value, m[3].str(), m[4].str());
    }
    return what;
}

}  // namespace

std::vector<std::string> with_help_command(std::vector<std::string> args, const CLI::App& app) {
    if (args.size() < 2 || args[1] != "help") return args;
    if (args.size() == 2) return {args[0], "--help"};
    const std::vector<std::string> names = command_names(app);
    if (std::find(names.begin(), names.end(), args[2]) == names.end()) return {args[0], args[2]};
    return {args[0], args[2], "--help"};
}

std::string closest_name(const std::string& typed, const std::vector<std::string>& names) {
    std::string best;
    std::size_t best_slips = 3;  // more than two slips is another word
    for (const std::string& n : names) {
        const std::size_t s = slips(typed, n);
        if (s < best_slips && s < std::max<std::size_t>(n.size() / 2, 1) + 1) {
            best = n;
            best_slips = s;
        }
    }
    return best;
}

std::string parse_error_text(const CLI::ParseError& e, const CLI::App& app, const std::vector<std::string>& args) {
    const std::vector<CLI::App*> parsed = app.get_subcommands();
    const CLI::App* sub = parsed.empty() ? &app : parsed.front();
    const std::string help = parsed.empty() ? "polyroll --help" : "polyroll " + sub->get_name() + " --help";
    // Before a command the only flag is --help: any error there is a missing or mistyped command.
    const std::string text = parsed.empty() ? unknown_command(app, args) : reworded(e.what(), *sub);
    return fmt::format("{} (see {})", text, help);
}

std::string flag_error_text(const CLI::ParseError& e, const CLI::App& app, const std::string& program,
                            const std::map<std::string, std::string>& allowed) {
    return fmt::format("{} (see {} --help)", reworded(e.what(), app, allowed), program);
}

}  // namespace polyroll::flags
