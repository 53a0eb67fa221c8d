// Range checks for scenes: see scene_validate.h.
#include "sim/scene_validate.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "sim/errors.h"
#include "sim/geometry.h"
#include "sim/shell_properties.h"

namespace polyroll {
namespace {

struct Checker {
    const std::function<std::string(const std::string&)>& where;

    std::string from(const std::string& field) const { return where ? where(field) : std::string(); }

    // min <= value <= max (or < max when max_open).
    void range(const std::string& field, double value, double min, double max, const std::string& unit = "",
               bool min_open = false, bool max_open = false) const {
        const bool ok = (min_open ? value > min : value >= min) && (max_open ? value < max : value <= max);
        if (ok) return;
        throw InputError(fmt::format("{} = {:g}{} is out of range (allowed: {} {:g} to {:g}{}{})", field, value,
                                     from(field), min_open ? "above" : "from", min, max,
                                     unit.empty() ? "" : " " + unit, max_open ? ", exclusive" : ""));
    }
    void irange(const std::string& field, int value, int min, int max) const {
        if (value >= min && value <= max) return;
        throw InputError(
            fmt::format("{} = {}{} is out of range (allowed: {} to {})", field, value, from(field), min, max));
    }
};

}  // namespace

double estimated_grain_count(const Scene& s) {
    if (s.fill.ratio <= 0.0) return 0.0;
    const ShellProperties p = shell_properties(s.shell);
    const double d = s.fill.material.diameter_m;
    // Hexagonal packing of discs covers pi / (2 sqrt 3) = 0.907 of the plane.
    return 0.907 * s.fill.ratio * p.inner_area_m2 / (geom::kPi * d * d / 4.0);
}

void validate_scene(const Scene& s, const std::function<std::string(const std::string&)>& where) {
    const Checker c{where};
    c.irange("shell.sides", s.shell.sides, 3, 64);
    c.range("shell.inner_circumradius_m", s.shell.inner_circumradius_m, 0.005, 1.0, "m");
    c.range("shell.wall_thickness_m", s.shell.wall_thickness_m, 0.0, 0.5 * s.shell.inner_circumradius_m, "m", true);
    c.range("shell.depth_m", s.shell.depth_m, 0.001, 2.0, "m");
    c.range("shell.lid_thickness_m", s.shell.lid_thickness_m, 0.0, 0.1, "m");
    c.range("shell.mass_kg", s.shell.mass_kg, 0.0, 100.0, "kg", true);
    if (s.shell.lid_mass_fraction) c.range("shell.lid_mass_fraction", *s.shell.lid_mass_fraction, 0.0, 1.0, "", false, true);

    c.range("fill.ratio", s.fill.ratio, 0.0, 1.0);
    const MaterialParams& m = s.fill.material;
    const double inner_apothem = geom::regular_polygon_apothem(s.shell.sides, s.shell.inner_circumradius_m);
    c.range("fill.material.diameter_spread", m.diameter_spread, 0.0, 0.5);
    // The largest grain must fit across the inside with room to move.
    c.range("fill.material.diameter_m", m.diameter_m, 0.0005, inner_apothem / (1.0 + m.diameter_spread), "m");
    c.range("fill.material.bulk_density_kg_m3", m.bulk_density_kg_m3, 0.0, 20000.0, "kg/m^3", true);
    c.range("fill.material.friction", m.friction, 0.0, 2.0);
    c.range("fill.material.wall_friction", m.wall_friction, 0.0, 2.0);
    c.range("fill.material.restitution", m.restitution, 0.0, 1.0);
    const double grains = estimated_grain_count(s);
    if (grains > kMaxGrains)
        throw InputError(fmt::format(
            "fill: about {:.0f} grains of fill.material.diameter_m = {:g} m{} in this shell is too many "
            "(allowed: at most {:.0f}; use larger grains, a smaller fill.ratio or a smaller shell)",
            grains, m.diameter_m, c.from("fill.material.diameter_m"), kMaxGrains));

    const double outer_r = shell_properties(s.shell).outer_circumradius_m;
    c.range("ramp.length_m", s.ramp.length_m, 4.0 * outer_r, 100.0, "m");
    c.range("ramp.friction", s.ramp.friction, 0.0, 2.0);
    c.range("ramp.restitution", s.ramp.restitution, 0.0, 1.0);
    c.range("ramp.angle_deg", s.ramp.angle_deg, 0.0, 89.0, "degrees");

    c.range("release.tilt_deg", s.release.tilt_deg, 0.0, 30.0, "degrees");
    {
        // The release turns the shell about its downhill vertex; past one face's turn (360/n degrees,
        // less the turn a vertex release already makes) the next vertex would start inside the ramp.
        const double face_turn_deg = 360.0 / s.shell.sides;
        const double balance_turn_deg =
            s.release.pose == ReleasePose::vertex ? std::max(0.0, 180.0 / s.shell.sides - s.ramp.angle_deg) : 0.0;
        const double max_tilt_deg = 0.9 * (face_turn_deg - balance_turn_deg);
        if (s.release.tilt_deg > max_tilt_deg)
            throw InputError(fmt::format(
                "release.tilt_deg = {:g}{} is too large for n = {} at {:g} degrees (allowed: 0 to {:.2f} degrees; "
                "more would start the next vertex inside the ramp)",
                s.release.tilt_deg, c.from("release.tilt_deg"), s.shell.sides, s.ramp.angle_deg, max_tilt_deg));
    }

    c.range("fidelity.step_hz", s.fidelity.step_hz, 30.0, 100000.0, "Hz");
    c.irange("fidelity.substeps", s.fidelity.substeps, 1, 100);
    c.irange("fidelity.velocity_iterations", s.fidelity.velocity_iterations, 1, 1000);
    c.irange("fidelity.position_iterations", s.fidelity.position_iterations, 1, 1000);

    c.range("run.time_limit_s", s.run.time_limit_s, 0.0, 3600.0, "s", true);
    c.range("run.sample_hz", s.run.sample_hz, 0.0, s.fidelity.step_hz, "Hz (at most fidelity.step_hz)", true);
    c.range("run.gravity_m_s2", s.run.gravity_m_s2, 0.0, 100.0, "m/s^2", true);
    c.range("run.settle_time_s", s.run.settle_time_s, 0.0, 60.0, "s");
    c.range("run.rest_speed_m_s", s.run.rest_speed_m_s, 0.0, 1.0, "m/s", true);
    c.range("run.rest_time_s", s.run.rest_time_s, 0.0, 60.0, "s", true);
}

}  // namespace polyroll
