// The 3D reference's input: see dem3d_input.h.
#include "sim/dem3d/dem3d_input.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "sim/geometry/fill_spheres.h"
#include "sim/geometry/shell_outline.h"
#include "sim/geometry/geometry.h"
#include "sim/scene/scene_names.h"
#include "sim/geometry/shell_pose.h"
#include "sim/geometry/shell_properties.h"

namespace polyroll::dem3d {

using json = nlohmann::ordered_json;

namespace {

// The smallest edge sphere: the spheres' soft contacts with the ramp overlap about a tenth of a
// millimetre under the shell's weight (1 ms contacts), so a sharper vertex is not one this engine can
// make; shell.vertex_radius_m below it (0: as sharp as the engine makes it) is this.
constexpr double kMinEdgeSphereRadius_m = 0.0001;

json points(const std::vector<geom::Vec2>& poly) {
    json a = json::array();
    for (const geom::Vec2& p : poly) a.push_back({p.x, p.y});
    return a;
}

}  // namespace

double edge_sphere_radius_m(const Scene& s) { return std::max(s.shell.vertex_radius_m, kMinEdgeSphereRadius_m); }

json script_input(const Scene& s, double frames_hz) {
    const ShellProperties p = shell_properties(s.shell);
    // The grains are poured with the shell held in the pour pose; the tipped release then turns shell
    // and pile about the pivot vertex by tip_rad into the release pose.
    const ShellPose pour = pour_pose(s, p);
    const ShellPose release = release_pose(s, p);
    // The shell's moment about an axis across the roll axis: walls and lids as a thin prism of the
    // outer radius and the box's length. The script blocks those rotations unless the box rolls in a channel
    // (dem3d.channel_width_m), where this estimate is what its yaw and tilt see.
    const double length_m = box_length_m(s.shell);
    const double cross_inertia = p.mass_kg * (p.outer_circumradius_m * p.outer_circumradius_m / 4.0 + length_m * length_m / 12.0);

    json j;
    j["seed"] = s.run.seed;
    j["gravity_m_s2"] = s.run.gravity_m_s2;
    j["angle_deg"] = s.ramp.angle_deg;
    j["ramp"] = {{"length_m", s.ramp.length_m},
                 {"curvature_deg_per_m", s.ramp.curvature_deg_per_m},
                 {"friction", s.ramp.friction},
                 {"restitution", s.ramp.restitution}};
    j["shell"] = {{"sides", s.shell.sides},
                  {"outer_vertices_m", points(shell_outer_polygon_m(s.shell))},
                  {"inner_vertices_m", points(shell_inner_polygon_m(s.shell))},
                  {"inner_depth_m", s.shell.depth_m},
                  {"lid_thickness_m", s.shell.lid_thickness_m},
                  {"mass_kg", p.mass_kg},
                  {"inertia_roll_kg_m2", p.inertia_kg_m2},
                  {"inertia_cross_kg_m2", cross_inertia}};
    j["release"] = {{"centre_m", {pour.centre_m.x, pour.centre_m.y}},
                    {"angle_rad", pour.angle_rad},
                    {"tip_rad", release.angle_rad - pour.angle_rad},
                    {"tilt_deg", s.release.tilt_deg},
                    {"pose", to_string(s.release.pose)}};
    j["pivot_vertex"] = 1;  // release_pose stands the shell on vertex 1, the downhill end of face (0, 1)
    j["end_centre_x_m"] = end_centre_x_m(s, p);
    const MaterialParams& m = s.fill.material;
    j["fill"] = {{"grain_count", fill_sphere_count(s)},
                 {"grain_diameter_m", m.diameter_m},
                 {"diameter_spread", m.diameter_spread},
                 {"grain_density_kg_m3", m.bulk_density_kg_m3 / m.packing_fraction},
                 {"friction", m.friction},
                 {"wall_friction", m.wall_friction},
                 {"restitution", m.restitution}};
    j["dem3d"] = {{"contact_time_s", s.dem3d.contact_time_s},
                  {"time_step_share", s.dem3d.time_step_share},
                  {"edge_radius_m", edge_sphere_radius_m(s)},
                  {"channel_width_m", s.dem3d.channel_width_m.value_or(0.0)}};  // 0: no channel
    j["step_hz"] = s.fidelity.step_hz;
    j["time_limit_s"] = s.run.time_limit_s;
    j["settle_time_s"] = s.run.settle_time_s;
    j["rest_speed_m_s"] = s.run.rest_speed_m_s;
    j["rest_time_s"] = s.run.rest_time_s;
    j["frames_hz"] = frames_hz;
    return j;
}

}  // namespace polyroll::dem3d
