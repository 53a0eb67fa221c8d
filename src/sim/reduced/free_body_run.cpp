// An empty shell's run after lift-off, revealed step by step: see free_body_run.h.
#include "sim/reduced/free_body_run.h"

#include <algorithm>
#include <cmath>

#include "sim/geometry/shell_outline.h"
#include "sim/model_choice.h"
#include "sim/reduced/reduced_models.h"
#include "sim/reduced/reveal.h"
#include "sim/run_snapshot.h"
#include "sim/geometry/shell_pose.h"
#include "sim/geometry/shell_properties.h"

namespace polyroll::models {

FreeBodyStart free_body_start(const HandOver& from, double step_hz) {
    FreeBodyStart s;
    s.time_s = static_cast<double>(from.steps) / step_hz;
    s.state = from.shell;
    s.release = from.release;
    s.potential_J = from.potential_J;
    s.landed_vertex = from.landed_vertex;
    s.measured = from.measured;
    return s;
}

FreeBodyRun::FreeBodyRun(const Scene& scene, const HandOver& from)
    : RevealedRun(scene, from.steps, from.measured), from_(from) {
    const ShellProperties sp = shell_properties(scene.shell);
    body_.outer_m = shell_outer_polygon_m(scene.shell);
    body_.mass_kg = sp.mass_kg;
    body_.inertia_kg_m2 = sp.inertia_kg_m2;
    // A full shell's fill turns with it (model_choice.h, fill_is_solid): a uniform polygon about the
    // same centre. A free body of a shell partly full would have its centre of mass off the centre,
    // which this body does not model; auto hands such shells to no free body.
    if (fill_is_solid(scene)) {
        const RollingBody b = rolling_body(scene);
        const geom::AreaProperties inside = geom::polygon_properties(b.inner_m);
        fill_mass_kg_ = b.fill_areal_density_kg_m2 * inside.area;
        body_.mass_kg += fill_mass_kg_;
        body_.inertia_kg_m2 += b.fill_areal_density_kg_m2 * inside.polar_moment_cm;
    }
    full_ = free_body_motion(body_, ramp_frame(scene), free_body_start(from, scene.fidelity.step_hz));
    if (full_.unsupported_time_s)
        hand_over_step_ = std::max(from.steps, static_cast<long>(std::floor(*full_.unsupported_time_s * scene.fidelity.step_hz)));
    reveal();
}

std::optional<FreeBodyRow> FreeBodyRun::row_now() const {
    if (steps_ <= from_.steps) return std::nullopt;
    return full_.row_at_step(steps_, scene_.fidelity.step_hz, from_.steps + 1);
}

ShellState FreeBodyRun::state_now() const {
    const std::optional<FreeBodyRow> r = row_now();
    return r ? r->state : from_.shell;
}

TrajectorySample FreeBodyRun::sample_now() const {
    if (const std::optional<FreeBodyRow> r = row_now()) return r->sample;
    TrajectorySample s = from_.measured.trajectory.empty() ? TrajectorySample{} : from_.measured.trajectory.back();
    s.time_s = time_s();
    s.potential_J = from_.potential_J;
    return s;
}

RunSnapshot FreeBodyRun::snapshot() const {
    RunSnapshot s = scene_snapshot_now();
    s.time_s = finished() ? full_.measured.end_time_s : time_s();
    const ShellState st = state_now();
    s.shell_centre_m = st.pose.centre_m;
    s.shell_angle_rad = st.pose.angle_rad;
    set_measured(s, sample_now(), shown_);
    // auto carries only empty and full shells on as a free body (model_registry.h): a full one's
    // fill is the whole inside.
    if (scene_.fill.ratio >= 1.0) s.fill_region_local_m = s.inner_local_m;
    return s;
}

RunResult FreeBodyRun::result() const {
    RunResult r;
    r.scene = scene_;
    r.shell = shell_properties(scene_.shell);
    r.measured = finished() ? full_.measured : shown_;
    r.grains = 0;
    r.fill_mass_kg = fill_mass_kg_;
    r.settled = true;
    r.steps = full_.steps;
    return r;
}

HandOver FreeBodyRun::hand_over() const {
    HandOver h;
    h.steps = steps_;
    h.shell = state_now();
    h.release = from_.release;
    h.measured = shown_;
    h.measured.behaviour = Behaviour::running;
    const std::optional<FreeBodyRow> r = row_now();
    h.landed_vertex = r ? r->landed_vertex : from_.landed_vertex;
    h.potential_J = sample_now().potential_J;
    return h;
}

}  // namespace polyroll::models
