// Fields, bounds and start values of a calibration: see calibration_params.h.
#include "sweep/calibration_params.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/core.h>

#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/scene/scene_fields.h"

namespace polyroll::sweep {
namespace {

using json = nlohmann::ordered_json;

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (std::size_t at = s.find(sep); at != std::string::npos; at = s.find(sep, start)) {
        out.push_back(s.substr(start, at - start));
        start = at + 1;
    }
    out.push_back(s.substr(start));
    return out;
}

std::optional<double> number_of(const std::string& text) {
    try {
        std::size_t used = 0;
        const double v = std::stod(text, &used);
        if (used != text.size() || !std::isfinite(v)) return std::nullopt;
        return v;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

std::string fittable_fields() {
    std::string out;
    for (const SceneField& f : scene_fields())
        if (f.type == FieldType::number || f.type == FieldType::optional_number)
            out += (out.empty() ? "" : ", ") + std::string(f.path);
    return out;
}

// "from 0 to 1" with the field's open ends and unit: what bounds may span.
std::string limits_text(const SceneField& f, double lo, double hi) {
    return fmt::format("bounds within the field's limits, {} {:g} to {} {:g}{}{}", f.min_open ? "above" : "from", lo,
                       f.max_open ? "below" : "", hi, f.unit.empty() ? "" : " ", f.unit);
}

}  // namespace

std::vector<CalibrationParam> parse_calibration_params(const std::string& text, const Scene& scene,
                                                       const ObservationFile& observations) {
    std::vector<CalibrationParam> out;
    if (text.empty()) throw InputError("--params is empty (allowed: FIELD[=FROM:TO],... of " + fittable_fields() + ")");
    const json& defaults = assets::file("calibration.json").at("bounds");
    for (const std::string& item : split(text, ',')) {
        const auto eq = item.find('=');
        CalibrationParam p;
        p.path = item.substr(0, eq);
        const auto field = std::find_if(scene_fields().begin(), scene_fields().end(),
                                        [&](const SceneField& f) { return f.path == p.path; });
        if (field == scene_fields().end())
            throw InputError(fmt::format("--params {}: not a scene field (allowed: {})", p.path, fittable_fields()));
        const SceneField& f = *field;
        if (f.type != FieldType::number && f.type != FieldType::optional_number)
            throw InputError(fmt::format("--params {}: not a continuous number, an optimiser cannot fit it (allowed: {})",
                                         p.path, fittable_fields()));
        for (const CalibrationParam& q : out)
            if (q.path == p.path) throw InputError(fmt::format("--params {}: given twice (allowed: each field once)", p.path));
        for (const Observation& ob : observations.observations) {
            bool sets = ob.scene.contains(p.path) || (p.path == "ramp.angle_deg" && ob.angle_range_deg);
            for (const auto& g : ob.grid) sets = sets || g.first == p.path;
            if (sets)
                throw InputError(fmt::format("--params {}: {}: observation '{}' sets it (allowed: a field no "
                                             "observation sets)", p.path, observations.origin, ob.id));
        }
        const double min = field_min(f, scene), max = field_max(f, scene);
        if (eq == std::string::npos) {
            if (defaults.contains(p.path)) {
                const json& b = defaults.at(p.path);
                p.lo = b.at("from").get<double>();
                p.hi = b.at("to").get<double>();
                p.bounds_from = "assets/calibration.json: " + b.at("reason").get<std::string>();
            } else {
                p.lo = min;
                p.hi = max;
                p.bounds_from = "the field's limits";
            }
        } else {
            const std::string range = item.substr(eq + 1);
            const std::vector<std::string> ends = split(range, ':');
            const auto lo = ends.size() == 2 ? number_of(ends[0]) : std::nullopt;
            const auto hi = ends.size() == 2 ? number_of(ends[1]) : std::nullopt;
            if (!lo || !hi || !(*lo < *hi))
                throw InputError(fmt::format("--params {}={}: not FROM:TO with FROM < TO (e.g. {}=0.2:0.8)", p.path,
                                             range, p.path));
            p.lo = *lo;
            p.hi = *hi;
            p.bounds_from = "--params";
        }
        // An open end cannot be evaluated: the search stays a hair inside it.
        const double width = max - min;
        if (f.min_open && p.lo <= min && eq == std::string::npos) p.lo = min + 1e-6 * width;
        if (f.max_open && p.hi >= max && eq == std::string::npos) p.hi = max - 1e-6 * width;
        if (p.lo < min || p.hi > max || (f.min_open && p.lo <= min) || (f.max_open && p.hi >= max))
            throw InputError(fmt::format("--params {}={:g}:{:g}: outside the field's limits (allowed: {})", p.path, p.lo,
                                         p.hi, limits_text(f, min, max)));
        out.push_back(p);
    }
    return out;
}

void set_start_values(std::vector<CalibrationParam>& params, const Scene& scene,
                      const std::vector<std::pair<std::string, double>>& starts) {
    for (const auto& start : starts)  // (no structured binding: clang 14 cannot capture one in a lambda)
        if (std::none_of(params.begin(), params.end(), [&](const CalibrationParam& p) { return p.path == start.first; }))
            throw InputError(fmt::format("--start {}={:g}: not a field of --params", start.first, start.second));
    for (CalibrationParam& p : params) {
        const auto given = std::find_if(starts.begin(), starts.end(), [&](const auto& s) { return s.first == p.path; });
        if (given != starts.end()) {
            p.start = given->second;
            p.start_from = "--start";
        } else {
            const FieldValue v = scene_field(p.path).access.get(scene);
            if (const auto* d = std::get_if<double>(&v)) {
                p.start = *d;
            } else if (const auto* o = std::get_if<std::optional<double>>(&v); o && *o) {
                p.start = **o;
            } else {
                throw InputError(fmt::format("--params {}: the scene has no value for it (null) (allowed: a start "
                                             "value with --start {}=VALUE)", p.path, p.path));
            }
            p.start_from = "the scene";
        }
        if (p.start < p.lo || p.start > p.hi)
            throw InputError(fmt::format("{} {}={:g}: outside the bounds (allowed: from {:g} to {:g}; --params {}=FROM:TO "
                                         "to widen them{})", p.start_from == "--start" ? "--start" : "the scene's",
                                         p.path, p.start, p.lo, p.hi, p.path,
                                         p.start_from == "--start" ? "" : ", or --start"));
    }
}

}  // namespace polyroll::sweep
