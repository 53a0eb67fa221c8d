// An empty shell's run after lift-off, revealed step by step: see free_body_run.h.
#include "sim/models/free_body_run.h"

#include <algorithm>
#include <cmath>

#include "sim/fill_plan.h"
#include "sim/model_choice.h"
#include "sim/models/reduced_models.h"
#include "sim/models/reveal.h"
#include "sim/run_snapshot.h"
#include "sim/shell_pose.h"
#include "sim/shell_properties.h"

namespace polyroll::models {

namespace {
FreeBodyStart start_from(const HandOver& from, double step_hz) {
    FreeBodyStart s;
    s.time_s = static_cast<double>(from.steps) / step_hz;
    s.state = from.shell;
    s.release = from.release;
    s.potential_J = from.potential_J;
    s.landed_vertex = from.landed_vertex;
    s.measured = from.measured;
    return s;
}
}  // namespace

FreeBodyRun::FreeBodyRun(const Scene& scene, const HandOver& from) : scene_(scene), from_(from) {
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
    rules_.angle_deg = scene.ramp.angle_deg;
    rules_.gravity_m_s2 = scene.run.gravity_m_s2;
    // Box2D mixes two fixtures' coefficients as sqrt(a b); the shell's fixtures carry the ramp's own.
    rules_.friction = scene.ramp.friction;
    rules_.end_centre_x_m = end_centre_x_m(scene, sp);
    rules_.time_limit_s = scene.run.time_limit_s;
    rules_.sample_hz = scene.run.sample_hz;
    rules_.sample_grid_hz = scene.fidelity.step_hz;
    rules_.rest_speed_m_s = scene.run.rest_speed_m_s;
    full_ = free_body_motion(body_, rules_, start_from(from, scene.fidelity.step_hz));
    if (full_.unsupported_time_s)
        hand_over_step_ = std::max(from.steps, static_cast<long>(std::floor(*full_.unsupported_time_s * scene.fidelity.step_hz)));
    outer_ = shell_outer_polygon_m(scene.shell);
    inner_ = shell_inner_polygon_m(scene.shell);
    steps_ = from.steps;
    shown_ = from.measured;
    shown_.behaviour = Behaviour::running;
    reveal();
}

const FreeBodyMotion& FreeBodyRun::fine() const {
    std::call_once(fine_once_, [this] {
        FreeBodyRules every_step = rules_;
        every_step.sample_hz = scene_.fidelity.step_hz;
        FreeBodyStart s = start_from(from_, scene_.fidelity.step_hz);
        s.measured.trajectory.clear();  // row i of the result is step from.steps + 1 + i
        s.first_row = from_.steps + 1;
        fine_ = free_body_motion(body_, every_step, s);
    });
    return fine_;
}

ShellState FreeBodyRun::state_now() const {
    if (steps_ <= from_.steps) return from_.shell;
    const FreeBodyMotion& f = fine();
    if (f.states.empty()) return from_.shell;
    const size_t i = std::min(static_cast<size_t>(steps_ - from_.steps - 1), f.states.size() - 1);
    return f.states[i];
}

TrajectorySample FreeBodyRun::sample_now() const {
    if (steps_ > from_.steps) {
        const FreeBodyMotion& f = fine();
        if (!f.measured.trajectory.empty()) {
            const size_t i =
                std::min(static_cast<size_t>(steps_ - from_.steps - 1), f.measured.trajectory.size() - 1);
            return f.measured.trajectory[i];
        }
    }
    TrajectorySample s = from_.measured.trajectory.empty() ? TrajectorySample{} : from_.measured.trajectory.back();
    s.time_s = time_s();
    s.potential_J = from_.potential_J;
    return s;
}

bool FreeBodyRun::finished() const {
    return !hand_over_step_ && time_s() >= full_.measured.end_time_s - 1e-12;
}

bool FreeBodyRun::step() {
    // Past the hand-over step the run has nothing to show: whoever runs it hands the shell over there.
    if (finished() || (hand_over_step_ && steps_ >= *hand_over_step_)) return false;
    ++steps_;
    reveal();
    return !finished();
}

void FreeBodyRun::run_to_end() {
    steps_ = hand_over_step_ ? std::max(steps_, *hand_over_step_)
                             : first_step_at_end(full_.measured.end_time_s, scene_.fidelity.step_hz, steps_);
    reveal();
}

RunSnapshot FreeBodyRun::snapshot() const {
    RunSnapshot s = scene_snapshot(scene_, outer_, inner_);
    s.time_s = finished() ? full_.measured.end_time_s : time_s();
    const ShellState st = state_now();
    s.shell_centre_m = st.pose.centre_m;
    s.shell_angle_rad = st.pose.angle_rad;
    set_measured(s, sample_now(), shown_);
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
    h.landed_vertex = from_.landed_vertex;
    if (steps_ > from_.steps && !fine().landed_vertices.empty())
        h.landed_vertex = fine().landed_vertices[std::min(static_cast<size_t>(steps_ - from_.steps - 1),
                                                          fine().landed_vertices.size() - 1)];
    h.potential_J = sample_now().potential_J;
    return h;
}

void FreeBodyRun::reveal() { reveal_up_to(shown_, full_.measured, time_s(), finished()); }

}  // namespace polyroll::models
