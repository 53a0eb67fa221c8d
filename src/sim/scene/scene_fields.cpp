// The table of scene fields: see scene_fields.h. The limits are the physical and practical bounds of
// each value (the reasons beside them); the messages that name them are in scene_validate.cpp.
#include "sim/scene/scene_fields.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/core.h>

#include "sim/geometry/geometry.h"
#include "sim/model_registry.h"
#include "sim/scene/scene_names.h"
#include "sim/geometry/shell_properties.h"
#include "sim/message_text.h"

namespace polyroll {
namespace {

// A row of the table, built by naming only what the field has.
class Row {
public:
    Row(std::string_view path, FieldType type, FieldAccess access) {
        f_.path = path;
        f_.type = type;
        f_.access = access;
    }
    Row& range(double min, double max) {
        f_.min = min;
        f_.max = max;
        return *this;
    }
    Row& min_open() { f_.min_open = true; return *this; }
    Row& max_open() { f_.max_open = true; return *this; }
    Row& min_of(double (*limit)(const Scene&), std::vector<std::string_view> depends_on) {
        f_.min_of = limit;
        f_.depends_on = std::move(depends_on);
        return *this;
    }
    Row& max_of(double (*limit)(const Scene&), std::vector<std::string_view> depends_on) {
        f_.max_of = limit;
        f_.depends_on = std::move(depends_on);
        return *this;
    }
    Row& unit(std::string_view unit, std::string_view note = "") {
        f_.unit = unit;
        f_.limit_note = note;
        return *this;
    }
    Row& presets(assets::Kind kind) { f_.kind = kind; return *this; }
    // An enumeration's names and lookup (scene_names.h).
    template <const std::vector<std::string>& (*Names)(), auto Named>
    Row& choices() {
        f_.choice_names = Names;
        f_.choice_named = [](std::string_view name) -> std::optional<FieldValue> {
            if (auto v = Named(name)) return FieldValue(*v);
            return std::nullopt;
        };
        return *this;
    }
    Row& flag(std::string_view flag, int sweep_axis = 0) {
        f_.flag = flag;
        f_.sweep_axis = sweep_axis;
        return *this;
    }
    Row& label(std::string_view label) { f_.label = label; return *this; }
    Row& help(std::string_view help) { f_.help = help; return *this; }
    operator SceneField() const { return f_; }  // so the table lists rows as fields

private:
    SceneField f_;
};

using T = FieldType;

// Limits that depend on other fields.
// Walls thicker than half the inner radius leave no room for the fill.
double max_wall_thickness_m(const Scene& s) { return 0.5 * s.shell.inner_circumradius_m; }
// A vertex's arc stays within the wall: its circle, tangent to both outer faces, reaches half the
// wall's thickness from each at a radius of half the wall; and 5 mm is already a shell with round
// corners, not a polygon's.
double max_vertex_radius_m(const Scene& s) { return std::min(0.005, 0.5 * s.shell.wall_thickness_m); }
// The largest grain must fit across the inside with room to move, in either model (the 2D discs may be
// spread wider by the closure).
double max_grain_diameter_m(const Scene& s) {
    const double spread = std::max(s.fill.material.diameter_spread, s.closure.disc_size_spread.value_or(0.0));
    return geom::regular_polygon_apothem(s.shell.sides, s.shell.inner_circumradius_m) / (1.0 + spread);
}
// The ramp must be at least two outer diameters long.
double min_ramp_length_m(const Scene& s) { return 4.0 * shell_properties(s.shell).outer_circumradius_m; }
// A curved track's local slope stays within -89 to 89 degrees at both ends (angle +- curvature x
// length / 2, the angle at least 0), and a curvature beyond 20 degrees per metre (a 2.9 m radius) is
// no longer a track that sags.
double max_ramp_curvature_deg_per_m(const Scene& s) {
    return std::min(20.0, 2.0 * (89.0 - s.ramp.angle_deg) / s.ramp.length_m);
}
double min_ramp_curvature_deg_per_m(const Scene& s) { return -max_ramp_curvature_deg_per_m(s); }
// A trajectory row is written at a tracker step: no more rows than steps.
double max_sample_hz(const Scene& s) { return s.fidelity.step_hz; }
// The channel must be wider than the box is long (lids included), or the box would start inside its sides.
double min_channel_width_m(const Scene& s) { return box_length_m(s.shell); }

// --model's help: every model's description from the registry, then auto's rule; kept for the
// table's lifetime, which holds it as a view.
std::string_view model_field_help() {
    static const std::string help = "physics: " + model_help(all_models());
    return help;
}

std::vector<SceneField> make_table() {
    using assets::Kind;
    return {
        // --- shell: the hollow polygon (assets/polygons.json)
        Row("shell.preset", T::preset, member<&Scene::shell, &ShellParams::preset>())
            .presets(Kind::polygon).flag("--polygon", 3).label("polygon")
            .help("polygon preset: the experiment's shell, its size, walls and mass"),
        Row("shell.sides", T::integer, member<&Scene::shell, &ShellParams::sides>())
            .range(3, 64).flag("--sides", 4).label("n (sides)")
            .help("n: the number of sides of the hollow polygon"),
        Row("shell.inner_circumradius_m", T::number, member<&Scene::shell, &ShellParams::inner_circumradius_m>())
            .range(0.005, 1.0).unit("m").help("inside centre-to-vertex radius R"),
        Row("shell.wall_thickness_m", T::number, member<&Scene::shell, &ShellParams::wall_thickness_m>())
            .range(0.0, 0.0).min_open().max_of(max_wall_thickness_m, {"shell.inner_circumradius_m"})
            .unit("m", "(at most half of shell.inner_circumradius_m)")
            .help("side walls' thickness, perpendicular to each face"),
        Row("shell.depth_m", T::number, member<&Scene::shell, &ShellParams::depth_m>())
            .range(0.001, 2.0).unit("m").help("inside length along the roll axis, between the lids"),
        Row("shell.lid_thickness_m", T::number, member<&Scene::shell, &ShellParams::lid_thickness_m>())
            .range(0.0, 0.1).unit("m").help("thickness of each of the two end faces"),
        Row("shell.mass_kg", T::number, member<&Scene::shell, &ShellParams::mass_kg>())
            .range(0.0, 100.0).min_open().unit("kg").help("empty mass: walls plus both lids"),
        Row("shell.lid_mass_fraction", T::optional_number, member<&Scene::shell, &ShellParams::lid_mass_fraction>())
            .range(0.0, 1.0).max_open()
            .help("share of the mass in the two lids; null: walls and lids of one material, split by volume"),
        Row("shell.vertex_radius_m", T::number, member<&Scene::shell, &ShellParams::vertex_radius_m>())
            .range(0.0, 0.005).max_of(max_vertex_radius_m, {"shell.wall_thickness_m"})
            .unit("m", "(at most 5 mm and half of shell.wall_thickness_m)").flag("--vertex-radius")
            .help("radius of the rounding of the shell's outer vertices, the corners it rolls over (the grain "
                  "simulation and the 3D reference; 0 as sharp as each engine makes them: Box2D's skin, 0.1 mm "
                  "spheres in 3D; the reduced models keep sharp vertices)"),

        // --- fill: how much of the inside the grains fill, and the grains (assets/materials.json)
        Row("fill.ratio", T::number, member<&Scene::fill, &FillParams::ratio>())
            .range(0.0, 1.0).flag("--fill", 6).label("r (fill)")
            .help("r: the share of the inside volume filled with grains, no unit"),
        Row("fill.material.preset", T::preset, member<&Scene::fill, &FillParams::material, &MaterialParams::preset>())
            .presets(Kind::material).flag("--material", 5).label("material")
            .help("material preset: the grains' size, density, friction and restitution"),
        Row("fill.material.diameter_m", T::number,
            member<&Scene::fill, &FillParams::material, &MaterialParams::diameter_m>())
            .range(0.0005, 0.0)
            .max_of(max_grain_diameter_m, {"shell.sides", "shell.inner_circumradius_m", "fill.material.diameter_spread",
                                             "closure.disc_size_spread"})
            .unit("m", "(at most the inside apothem over 1 + fill.material.diameter_spread)").help("mean grain diameter"),
        Row("fill.material.diameter_spread", T::number,
            member<&Scene::fill, &FillParams::material, &MaterialParams::diameter_spread>())
            .range(0.0, 0.5).help("grain diameters are uniform in d (1 +- spread)"),
        Row("fill.material.bulk_density_kg_m3", T::number,
            member<&Scene::fill, &FillParams::material, &MaterialParams::bulk_density_kg_m3>())
            .range(0.0, 20000.0).min_open().unit("kg/m^3").help("poured bulk density: mass per bulk volume"),
        Row("fill.material.friction", T::number, member<&Scene::fill, &FillParams::material, &MaterialParams::friction>())
            .range(0.0, 2.0).label("grain friction").help("friction coefficient between grains, no unit"),
        Row("fill.material.wall_friction", T::number,
            member<&Scene::fill, &FillParams::material, &MaterialParams::wall_friction>())
            .range(0.0, 2.0).help("friction coefficient between grains and the shell's walls, no unit"),
        Row("fill.material.lid_friction", T::number,
            member<&Scene::fill, &FillParams::material, &MaterialParams::lid_friction>())
            .range(0.0, 2.0)
            .help("friction coefficient between grains and the two lids (end faces), no unit; 0 leaves the term out"),
        Row("fill.material.restitution", T::number,
            member<&Scene::fill, &FillParams::material, &MaterialParams::restitution>())
            .range(0.0, 1.0).label("grain restitution")
            .help("restitution of grain impacts on grains and walls (0 no bounce, 1 elastic), no unit"),
        Row("fill.material.packing_fraction", T::number,
            member<&Scene::fill, &FillParams::material, &MaterialParams::packing_fraction>())
            .range(0.3, 0.74)
            .help("share of the poured fill's bulk volume taken by grains (bulk density / grain density), no unit; "
                  "counts the 3D fill's grains for fill.material.grains_per_disc"),
        Row("fill.material.grains_per_disc", T::optional_number,
            member<&Scene::fill, &FillParams::material, &MaterialParams::grains_per_disc>())
            .range(1.0, 1000.0)
            .help("how many of the 3D fill's grains one 2D disc stands for (1: one disc per grain, discs sized to "
                  "fit the cross-section); null: a column through the box's depth, discs of the grain's size"),

        // --- ramp (assets/ramps.json)
        Row("ramp.preset", T::preset, member<&Scene::ramp, &RampParams::preset>())
            .presets(Kind::ramp).flag("--ramp", 7).label("ramp").help("ramp preset: its length, friction and restitution"),
        Row("ramp.length_m", T::number, member<&Scene::ramp, &RampParams::length_m>())
            .range(0.0, 100.0)
            .min_of(min_ramp_length_m, {"shell.sides", "shell.inner_circumradius_m", "shell.wall_thickness_m"})
            .unit("m").help("length of the ramp"),
        Row("ramp.friction", T::number, member<&Scene::ramp, &RampParams::friction>())
            .range(0.0, 2.0).label("ramp friction").help("friction coefficient between the shell and the ramp, no unit"),
        Row("ramp.restitution", T::number, member<&Scene::ramp, &RampParams::restitution>())
            .range(0.0, 1.0).label("ramp restitution")
            .help("restitution of the shell's impacts on the ramp (0 no bounce, 1 elastic), no unit"),
        Row("ramp.angle_deg", T::number, member<&Scene::ramp, &RampParams::angle_deg>())
            .range(0.0, 89.0).unit("degrees").flag("--angle", 8).label("\u03B8 (angle)")
            .help("\u03B8: the ramp's angle from horizontal (on a curved track, its chord's)"),
        Row("ramp.curvature_deg_per_m", T::number, member<&Scene::ramp, &RampParams::curvature_deg_per_m>())
            .range(-20.0, 20.0)
            .min_of(min_ramp_curvature_deg_per_m, {"ramp.length_m", "ramp.angle_deg"})
            .max_of(max_ramp_curvature_deg_per_m, {"ramp.length_m", "ramp.angle_deg"})
            .unit("degrees per metre", "(less where the slope at either end of the track would pass -89 or 89 degrees)")
            .flag("--curvature", 12)
            .help("how fast the track's slope falls down it, about its chord at ramp.angle_deg: a track that "
                  "sags between its supports is steeper at the top and shallower at the bottom (the local "
                  "slope is angle + curvature x (length/2 - x)); 0 is a straight track, negative a hump"),

        // --- release
        Row("release.pose", T::choice, member<&Scene::release, &ReleaseParams::pose>())
            .choices<release_pose_names, release_pose_named>().flag("--release", 9).label("release")
            .help("release pose: filled and held on a vertex with the centre above it (vertex), filled and set down "
                  "on a face (face), or filled on a face and then tipped onto the vertex (tipped)"),
        Row("release.tilt_deg", T::number, member<&Scene::release, &ReleaseParams::tilt_deg>())
            .range(0.0, 30.0).unit("degrees").flag("--tilt", 10)
            .help("release tilt past balance"),
        Row("release.pile_tilt_deg", T::number, member<&Scene::release, &ReleaseParams::pile_tilt_deg>())
            .range(-30.0, 30.0).unit("degrees")
            .help("2D grain model: the pile's free surface at release, turned from level by this (positive: "
                  "higher on the downhill side)"),

        // --- fidelity (assets/fidelity.json)
        Row("fidelity.preset", T::preset, member<&Scene::fidelity, &FidelityParams::preset>())
            .presets(Kind::fidelity).flag("--fidelity", 2).label("fidelity")
            .help("fidelity preset: time step and solver iterations, from draft (fastest) to reference (most accurate)"),
        Row("fidelity.step_hz", T::number, member<&Scene::fidelity, &FidelityParams::step_hz>())
            .range(30.0, 100000.0).unit("Hz").flag("--step-hz").help("tracker steps per simulated second"),
        Row("fidelity.substeps", T::integer, member<&Scene::fidelity, &FidelityParams::substeps>())
            .range(1, 100).flag("--substeps").help("engine steps per tracker step"),
        Row("fidelity.velocity_iterations", T::integer, member<&Scene::fidelity, &FidelityParams::velocity_iterations>())
            .range(1, 1000).flag("--velocity-iterations").help("solver velocity iterations"),
        Row("fidelity.position_iterations", T::integer, member<&Scene::fidelity, &FidelityParams::position_iterations>())
            .range(1, 1000).flag("--position-iterations").help("solver position iterations"),
        Row("fidelity.frame", T::choice, member<&Scene::fidelity, &FidelityParams::frame>())
            .choices<engine_frame_names, engine_frame_named>().flag("--frame")
            .help("the frame the grain engine steps in: the ramp's (ramp), or one moving down the track with the "
                  "pile (pile), the same motion in exact arithmetic with shorter contact lists; every output is "
                  "in the ramp's frame either way"),
        Row("fidelity.contacts", T::choice, member<&Scene::fidelity, &FidelityParams::contacts>())
            .choices<grain_contacts_names, grain_contacts_named>().flag("--contacts")
            .help("which pairs of grains the grain engine keeps a contact for: every pair whose boxes, fattened "
                  "by Box2D's margin (1 mm at the usual 1 cm engine unit), overlap (boxes, Box2D's own), or only pairs that touch or nearly "
                  "touch (near), the same motion in exact arithmetic with a fraction of the contacts"),

        // --- run
        Row("run.model", T::choice, member<&Scene::run, &RunParams::model>())
            .choices<model_names, model_named>().flag("--model", 1).label("model")
            .help(model_field_help()),
        Row("run.seed", T::seed, member<&Scene::run, &RunParams::seed>())
            .flag("--seed").help("random seed for the grain packing"),
        Row("run.time_limit_s", T::number, member<&Scene::run, &RunParams::time_limit_s>())
            .range(0.0, 3600.0).min_open().unit("s").flag("--time-limit", 11).help("longest simulated time"),
        Row("run.sample_hz", T::number, member<&Scene::run, &RunParams::sample_hz>())
            .range(0.0, 0.0).min_open().max_of(max_sample_hz, {"fidelity.step_hz"})
            .unit("Hz", "(at most fidelity.step_hz)").flag("--sample-hz").help("trajectory rows per simulated second"),
        Row("run.gravity_m_s2", T::number, member<&Scene::run, &RunParams::gravity_m_s2>())
            .range(0.0, 100.0).min_open().unit("m/s^2").help("gravitational acceleration"),
        Row("run.settle_time_s", T::number, member<&Scene::run, &RunParams::settle_time_s>())
            .range(0.0, 60.0).unit("s").help("longest time given to the grains to settle before release"),
        Row("run.rest_speed_m_s", T::number, member<&Scene::run, &RunParams::rest_speed_m_s>())
            .range(0.0, 1.0).min_open().unit("m/s").help("the shell counts as at rest below this speed..."),
        Row("run.rest_time_s", T::number, member<&Scene::run, &RunParams::rest_time_s>())
            .range(0.0, 60.0).min_open().unit("s").help("... held for this long"),
        Row("run.end_at_impact", T::integer, member<&Scene::run, &RunParams::end_at_impact>())
            .range(0, 100000)
            .help("the run ends at this face impact whatever the shell does next (behaviour time_limit, its summary "
                  "says it ended early): calibrate's early exit where an observation is decided; 0: never"),

        // --- dem3d: only the 3D reference (--model dem3d) reads these
        Row("dem3d.contact_time_s", T::number, member<&Scene::dem3d, &Dem3dParams::contact_time_s>())
            .range(1e-5, 0.01).unit("s").flag("--contact-time")
            .help("3D reference: how long one grain collision lasts (its spring's stiffness); shorter is stiffer, "
                  "truer and slower"),
        Row("dem3d.time_step_share", T::number, member<&Scene::dem3d, &Dem3dParams::time_step_share>())
            .range(0.01, 0.2).flag("--time-step-share")
            .help("3D reference: the time step as a share of dem3d.contact_time_s, no unit"),
        Row("dem3d.channel_width_m", T::optional_number, member<&Scene::dem3d, &Dem3dParams::channel_width_m>())
            .range(0.0, 1.0).min_open()
            .min_of(min_channel_width_m, {"shell.depth_m", "shell.lid_thickness_m"}).unit("m")
            .flag("--channel-width")
            .help("3D reference: width of the track's channel; the box, free in all six directions, rolls "
                  "between its sides. null: the box held in its plane, as the 2D cross-section is"),

        // --- closure: only the 2D grain model reads these (assets/closures.json)
        Row("closure.preset", T::preset, member<&Scene::closure, &ClosureParams::preset>())
            .presets(Kind::closure).flag("--closure", 13).label("closure")
            .help("2D grain model: what stands in for the third dimension the one-grain-deep pile lacks, fitted "
                  "to the 3D reference (none: the contacts as the material gives them)"),
        Row("closure.disc_friction_factor", T::number, member<&Scene::closure, &ClosureParams::disc_friction_factor>())
            .range(0.0, 2.0)
            .help("2D grain model: disc-on-disc friction as a share of fill.material.friction (below 1: grains "
                  "slipping out of the plane), no unit"),
        Row("closure.wall_friction_factor", T::number, member<&Scene::closure, &ClosureParams::wall_friction_factor>())
            .range(0.0, 2.0)
            .help("2D grain model: disc-on-wall friction as a share of fill.material.wall_friction, no unit"),
        Row("closure.restitution_factor", T::number, member<&Scene::closure, &ClosureParams::restitution_factor>())
            .range(0.0, 5.0)
            .help("2D grain model: the discs' restitution as a share of fill.material.restitution (at most 1 "
                  "in all), no unit"),
        Row("closure.disc_size_spread", T::optional_number, member<&Scene::closure, &ClosureParams::disc_size_spread>())
            .range(0.0, 0.5)
            .help("2D grain model: the discs' diameters uniform in d (1 +- this) instead of "
                  "fill.material.diameter_spread (a 3D pile's disorder: equal discs in a plane lock into a "
                  "crystal, equal spheres in a box do not); null: the material's, no unit"),
        Row("closure.bulk_factor", T::number, member<&Scene::closure, &ClosureParams::bulk_factor>())
            .range(0.5, 2.0)
            .help("2D grain model: the pile's level holds r times this of the inside (at most all of it), "
                  "the fill's mass unchanged (a 3D pour packs looser than the bulk density assumes, so its "
                  "pile stands higher), no unit"),
    };
}

}  // namespace

const std::vector<SceneField>& scene_fields() {
    static const std::vector<SceneField> table = make_table();
    return table;
}

const SceneField& scene_field(std::string_view path) {
    for (const SceneField& f : scene_fields())
        if (f.path == path) return f;
    throw std::logic_error(fmt::format("'{}' is not a scene field", path));
}

std::string_view section_of(std::string_view path) {
    const auto dot = path.rfind('.');
    return dot == std::string_view::npos ? std::string_view() : path.substr(0, dot);
}

std::string_view key_of(std::string_view path) {
    const auto dot = path.rfind('.');
    return dot == std::string_view::npos ? path : path.substr(dot + 1);
}

double field_min(const SceneField& f, const Scene& s) { return f.min_of ? f.min_of(s) : f.min; }
double field_max(const SceneField& f, const Scene& s) { return f.max_of ? f.max_of(s) : f.max; }

std::vector<std::string> field_choices(const SceneField& f) {
    if (f.type == FieldType::preset && f.kind) return assets::preset_names(*f.kind);
    if (f.type == FieldType::choice && f.choice_names) return f.choice_names();
    return {};
}

std::string field_allowed(const SceneField& f) {
    switch (f.type) {
        case FieldType::preset:
            // Help texts are built before a command runs; an unreadable replacement asset file is
            // reported by the command itself, not while its help is set up.
            try {
                return comma_list(field_choices(f));
            } catch (const std::exception&) {
                return "see 'polyroll presets'";
            }
        case FieldType::choice: return comma_list(field_choices(f));
        case FieldType::seed: return "0 to 2^64-1";
        case FieldType::integer: return fmt::format("{:g} to {:g}", f.min, f.max);
        case FieldType::number:
        case FieldType::optional_number: break;
    }
    const std::string unit = f.unit.empty() ? std::string() : " " + std::string(f.unit);
    const std::string note = f.limit_note.empty() ? std::string() : " " + std::string(f.limit_note);
    const std::string from = fmt::format("{} {:g}", f.min_open ? "above" : "from", f.min);
    if (f.min_of && f.max_of) return fmt::format("{:g} to {:g}{}{}", f.min, f.max, unit, note);
    if (f.max_of) return from + unit + note;
    if (f.min_of) return fmt::format("up to {:g}{}{}", f.max, unit, note);
    return fmt::format("{} to {:g}{}{}{}", from, f.max, unit, f.max_open ? ", exclusive" : "", note);
}

std::string field_help(const SceneField& f) {
    const std::string allowed = field_allowed(f);
    if (f.type == FieldType::preset || f.type == FieldType::choice) return fmt::format("{} ({})", f.help, allowed);
    return allowed.empty() ? std::string(f.help) : fmt::format("{}: {}", f.help, allowed);
}

}  // namespace polyroll
