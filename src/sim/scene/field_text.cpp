// Typed text as a scene field's value: see field_text.h.
#include "sim/scene/field_text.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <system_error>

#include <fmt/core.h>

#include "sim/errors.h"

namespace polyroll {
namespace {

// Digits with an optional leading '-' (a whole number as people type one: no '+', no spaces, no "1e3").
bool whole_number_text(std::string_view text) {
    const std::string_view digits = !text.empty() && text.front() == '-' ? text.substr(1) : text;
    return !digits.empty() && digits.find_first_not_of("0123456789") == std::string_view::npos;
}

// The whole text as a finite number (strtod's syntax: "0.25", "1e-3", ".5").
bool finite_number_text(std::string_view text) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return false;
    const std::string s(text);
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size() && errno != ERANGE && std::isfinite(v);
}

template <class T>
bool fits(std::string_view text) {
    T value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc() && end == text.data() + text.size();
}

}  // namespace

std::string field_text_problem(const SceneField& f, std::string_view text) {
    const std::string allowed = " (allowed: " + field_allowed(f) + ")";
    switch (f.type) {
        case FieldType::integer:
            if (!whole_number_text(text)) return "not a whole number" + allowed;
            return fits<int>(text) ? "" : "out of range" + allowed;
        case FieldType::seed:
            if (!whole_number_text(text) || text.front() == '-') return "not a whole number" + allowed;
            return fits<std::uint64_t>(text) ? "" : "out of range" + allowed;
        case FieldType::optional_number:
            if (text == "null") return "";
            [[fallthrough]];
        case FieldType::number: return finite_number_text(text) ? "" : "not a number" + allowed;
        case FieldType::preset:
        case FieldType::choice: break;
    }
    return "";
}

nlohmann::ordered_json field_json_from_text(const SceneField& f, const std::string& text, const std::string& said) {
    if (const std::string problem = field_text_problem(f, text); !problem.empty())
        throw InputError(fmt::format("{}: {}", said, problem));
    switch (f.type) {
        case FieldType::integer: return std::stoi(text);
        case FieldType::seed: return std::stoull(text);
        case FieldType::optional_number:
            if (text == "null") return nullptr;
            return std::strtod(text.c_str(), nullptr);
        case FieldType::number: return std::strtod(text.c_str(), nullptr);
        case FieldType::preset:
        case FieldType::choice: break;
    }
    return text;
}

std::string field_key(const SceneField& f) {
    std::string_view flag = f.flag;
    while (!flag.empty() && flag.front() == '-') flag.remove_prefix(1);
    return std::string(flag);
}

}  // namespace polyroll
