// Range checks for scenes: see scene_validate.h. The limits are the rows of scene_fields.cpp; the
// checks that span several fields (the grain count, the release tilt, the model on a curved track)
// are here, after their section.
#include "sim/scene/scene_validate.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string_view>

#include <fmt/core.h>

#include "sim/geometry/disc_size.h"
#include "sim/errors.h"
#include "sim/geometry/geometry.h"
#include "sim/model_registry.h"
#include "sim/geometry/ramp_profile.h"
#include "sim/scene/scene_names.h"
#include "sim/scene/scene_fields.h"
#include "sim/geometry/shell_pose.h"
#include "sim/geometry/shell_properties.h"

namespace polyroll {
namespace {

using Where = std::function<std::string(const std::string&)>;

std::string from(const Where& where, const std::string& field) { return where ? where(field) : std::string(); }

// min <= value <= max (strictly where a limit is open); throws naming the field and its range.
void check_range(const SceneField& f, const Scene& s, const Where& where) {
    const std::string field(f.path);
    const FieldValue v = f.access.get(s);
    const double min = field_min(f, s), max = field_max(f, s);
    if (f.type == FieldType::integer) {
        const int i = std::get<int>(v);
        if (i >= min && i <= max) return;
        throw InputError(fmt::format("{} = {}{} is out of range (allowed: {} to {})", field, i, from(where, field),
                                     static_cast<int>(min), static_cast<int>(max)));
    }
    double value = 0.0;
    if (f.type == FieldType::number) value = std::get<double>(v);
    else if (f.type == FieldType::optional_number && std::get<std::optional<double>>(v))
        value = *std::get<std::optional<double>>(v);
    else return;  // no limits: presets, choices, the seed, an empty optional
    const bool ok = (f.min_open ? value > min : value >= min) && (f.max_open ? value < max : value <= max);
    if (ok) return;
    std::string unit(f.unit);
    if (!f.limit_note.empty()) unit += " " + std::string(f.limit_note);
    throw InputError(fmt::format("{} = {:g}{} is out of range (allowed: {} {:g} to {:g}{}{})", field, value,
                                 from(where, field), f.min_open ? "above" : "from", min, max,
                                 unit.empty() ? "" : " " + unit, f.max_open ? ", exclusive" : ""));
}

// Discs sized from fill.material.grains_per_disc must fit the shell and the engine as grains of that
// size would (the limits of fill.material.diameter_m), and the fill must not need more discs than a
// run can afford.
void check_grain_count(const Scene& s, const Where& where) {
    const double disc_m = disc_diameter_m(s);
    const std::optional<double>& per_disc = s.fill.material.grains_per_disc;
    if (per_disc) {
        const SceneField& d = scene_field("fill.material.diameter_m");
        const double min_m = field_min(d, s), max_m = field_max(d, s);
        if (disc_m < min_m || disc_m > max_m)
            throw InputError(fmt::format(
                "fill.material.grains_per_disc = {:g}{} makes discs {:g} m across (allowed: {:g} to {:g} m, the "
                "limits of fill.material.diameter_m)",
                *per_disc, from(where, "fill.material.grains_per_disc"), disc_m, min_m, max_m));
    }
    const double grains = estimated_grain_count(s);
    if (grains > kMaxGrains) {
        const std::string field = per_disc ? "fill.material.grains_per_disc" : "fill.material.diameter_m";
        const double value = per_disc ? *per_disc : s.fill.material.diameter_m;
        throw InputError(fmt::format(
            "fill: about {:.0f} grains {:g} m across ({} = {:g}{}) in this shell is too many "
            "(allowed: at most {:.0f}; use larger grains, a smaller fill.ratio or a smaller shell)",
            grains, disc_m, field, value, from(where, field), kMaxGrains));
    }
}

// The release turns the shell about its downhill vertex; past one face's turn (360/n degrees, less the
// turn a vertex release already makes) the next vertex would start inside the ramp.
void check_release_tilt(const Scene& s, const Where& where) {
    const double face_turn_deg = 360.0 / s.shell.sides;
    const double balance_turn_deg =
        released_on_vertex(s.release) ? std::max(0.0, 180.0 / s.shell.sides - s.ramp.angle_deg) : 0.0;
    const double max_tilt_deg = 0.9 * (face_turn_deg - balance_turn_deg);
    if (s.release.tilt_deg > max_tilt_deg)
        throw InputError(fmt::format(
            "release.tilt_deg = {:g}{} is too large for n = {} at {:g} degrees (allowed: 0 to {:.2f} degrees; "
            "more would start the next vertex inside the ramp)",
            s.release.tilt_deg, from(where, "release.tilt_deg"), s.shell.sides, s.ramp.angle_deg, max_tilt_deg));
}

// A model that assumes one slope cannot run a curved track (every model in the registry follows one
// today; the check stays for the next that does not).
void check_model_on_track(const Scene& s, const Where& where) {
    if (!ramp_is_curved(s.ramp) || s.run.model == Model::automatic) return;
    if (model_traits(s.run.model).follows_curved_track) return;
    std::string can;
    for (Model m : all_models())
        if (model_traits(m).follows_curved_track) can += to_string(m) + ", ";
    throw InputError(fmt::format("run.model = {}{} cannot run a curved track (ramp.curvature_deg_per_m = {:g}{}; "
                                 "it assumes one slope): use {}auto, or a straight track (0)",
                                 to_string(s.run.model), from(where, "run.model"), s.ramp.curvature_deg_per_m,
                                 from(where, "ramp.curvature_deg_per_m"), can));
}

// Checks across fields, each run once every field of its section has passed its own range.
struct CrossCheck {
    std::string_view after_section;
    void (*check)(const Scene&, const Where&);
};
constexpr CrossCheck kCrossChecks[] = {
    {"fill", check_grain_count}, {"release", check_release_tilt}, {"run", check_model_on_track}};

std::string_view top_section(std::string_view path) { return path.substr(0, path.find('.')); }

}  // namespace

double estimated_grain_count(const Scene& s) {
    if (s.fill.ratio <= 0.0) return 0.0;
    const ShellProperties p = shell_properties(s.shell);
    const double d = disc_diameter_m(s);
    // Hexagonal packing of discs covers pi / (2 sqrt 3) = 0.907 of the plane.
    return 0.907 * pile_bulk_share(s) * p.inner_area_m2 / (geom::kPi * d * d / 4.0);
}

void validate_scene(const Scene& s, const Where& where) {
    // In table order, but a field whose limits read other fields comes after them, so a message
    // always names the field that is wrong rather than one whose limit it spoiled.
    std::set<std::string_view> checked;
    auto check = [&](const SceneField& f, auto& self) -> void {
        if (!checked.insert(f.path).second) return;
        for (std::string_view dep : f.depends_on) self(scene_field(dep), self);
        check_range(f, s, where);
    };
    const auto& fields = scene_fields();
    for (size_t i = 0; i < fields.size(); ++i) {
        check(fields[i], check);
        const std::string_view section = top_section(fields[i].path);
        if (i + 1 < fields.size() && top_section(fields[i + 1].path) == section) continue;
        for (const CrossCheck& c : kCrossChecks)
            if (c.after_section == section) c.check(s, where);
    }
}

}  // namespace polyroll
