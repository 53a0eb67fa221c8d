// Parsing swept values: see grid_values.h.
#include "sweep/grid_values.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "sim/errors.h"

namespace polyroll::sweep {
namespace {

using json = nlohmann::ordered_json;

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return "";
    const auto e = s.find_last_not_of(" \t");
    return s.substr(b, e - b + 1);
}

std::optional<double> parse_number(const std::string& s) {
    if (s.empty()) return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
    return v;
}

bool looks_integral(const std::string& s) {
    return s.find_first_of(".eE") == std::string::npos;
}

// Whole numbers as JSON integers (unsigned when >= 0, as run.seed requires), others as doubles.
json number_json(double v, bool integral) {
    if (integral && std::fabs(v) < 9.0e15 && v == std::floor(v)) {
        if (v >= 0) return json(static_cast<std::uint64_t>(v));
        return json(static_cast<std::int64_t>(v));
    }
    return json(v);
}

double snap(double v) {
    if (v == 0.0) return 0.0;
    return std::strtod(fmt::format("{:.12g}", v).c_str(), nullptr);
}

}  // namespace

std::vector<double> inclusive_range(const std::string& name, double start, double stop, double step,
                                    std::size_t max_values) {
    if (!(step > 0.0))
        throw InputError(fmt::format("{}: range step {:g} is not allowed (allowed: a step above 0)", name, step));
    if (stop < start)
        throw InputError(fmt::format("{}: range {:g}:{:g} runs backwards (allowed: start <= stop)", name, start, stop));
    // The tolerance keeps 0:1:0.1 at 11 values even though (1 - 0) / 0.1 is 9.999999999999998.
    const double span = (stop - start) / step;
    const double count = std::floor(span + 1e-9 * std::max(1.0, span)) + 1.0;
    if (count > static_cast<double>(max_values))
        throw InputError(fmt::format("{}: range {:g}:{:g}:{:g} has {:.0f} values (allowed: at most {})", name, start,
                                     stop, step, count, max_values));
    std::vector<double> values;
    for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
        double v = snap(start + static_cast<double>(i) * step);
        values.push_back(std::min(v, stop));
    }
    return values;
}

std::vector<json> parse_grid_values(const std::string& name, const std::string& text) {
    std::vector<json> values;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        const std::size_t comma = text.find(',', pos);
        const std::string item = trim(text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos));
        pos = comma == std::string::npos ? text.size() + 1 : comma + 1;
        if (item.empty())
            throw InputError(fmt::format("{} = '{}': empty item (allowed: a list a,b,c and ranges start:stop:step)",
                                         name, text));
        if (item.find(':') != std::string::npos) {
            std::vector<std::string> parts;
            std::size_t p = 0;
            for (std::size_t c = item.find(':'); ; c = item.find(':', p)) {
                parts.push_back(trim(item.substr(p, c == std::string::npos ? std::string::npos : c - p)));
                if (c == std::string::npos) break;
                p = c + 1;
            }
            std::optional<double> a, b, s;
            if (parts.size() == 3) a = parse_number(parts[0]), b = parse_number(parts[1]), s = parse_number(parts[2]);
            if (!a || !b || !s)
                throw InputError(fmt::format(
                    "{}: '{}' is not a range (allowed: start:stop:step, three numbers, stop inclusive)", name, item));
            const bool integral = looks_integral(parts[0]) && looks_integral(parts[2]);
            for (double v : inclusive_range(name, *a, *b, *s)) values.push_back(number_json(v, integral));
        } else if (auto v = parse_number(item)) {
            values.push_back(number_json(*v, looks_integral(item)));
        } else if (item == "null") {
            // An optional field's "not set" (fill.material.grains_per_disc=null: column discs).
            values.push_back(json(nullptr));
        } else {
            values.push_back(json(item));
        }
    }
    return values;
}

std::string value_text(const json& v) {
    if (v.is_string()) return v.get<std::string>();
    if (v.is_number_float()) return fmt::format("{}", v.get<double>());  // shortest round-trip form
    return v.dump();
}

}  // namespace polyroll::sweep
