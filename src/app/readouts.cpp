// Lane readouts as text: see readouts.h.
#include "app/readouts.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "render/overlay.h"
#include "sim/model_registry.h"
#include "sim/scene/scene_names.h"

namespace polyroll::app {

std::string behaviour_label(Behaviour b) {
    switch (b) {
        case Behaviour::running: return "rolling";
        case Behaviour::stopped_at_first_impact: return "stopped at 1st impact";
        case Behaviour::stopped: return "stopped";
        case Behaviour::rolled_to_end: return "rolled to the end";
        case Behaviour::time_limit: return "time limit reached";
        case Behaviour::diverged: return "diverged";
    }
    return "unknown";
}

namespace {

// The model row in parts: "auto: " or "", the model running now, and since when once it took over.
struct ModelLabel {
    std::string prefix;
    Model running;
    std::string name;   // the model's name, or "rigid, hops" for the rigid body free to lift off
    std::string since;  // " from 0.41 s", or "" for the model the run started with
};

ModelLabel model_label_parts(const Scene& scene, const ModelChoice* choice) {
    if (!choice) return {"", scene.run.model, to_string(scene.run.model), ""};
    // Say which model runs now, and since when: the rigid body on the ramp, then free to fly from
    // lift-off, then Box2D where the rigid body meets a contact it does not model.
    if (choice->then && choice->hand_over_time_s)
        return {"auto: ", *choice->then, to_string(*choice->then), fmt::format(" from {:.2f} s", *choice->hand_over_time_s)};
    if (choice->then && choice->lift_off_time_s)
        return {"auto: ", choice->model, "rigid, hops", fmt::format(" from {:.2f} s", *choice->lift_off_time_s)};
    return {"auto: ", choice->model, to_string(choice->model), ""};
}

}  // namespace

std::string model_label(const Scene& scene, const ModelChoice* choice) {
    const ModelLabel l = model_label_parts(scene, choice);
    return l.prefix + l.name + l.since;
}

LaneReadout lane_readout(const Scene& scene, const Measurements& m, double time_s, const ModelChoice* choice) {
    LaneReadout r;
    // A full shell reads "full of BBs", not "r = 1 BBs": its fill is one rigid body with it.
    const std::string material = render::material_label(scene.fill.material.preset);
    const bool full = scene.fill.ratio >= 1.0;
    const std::string fill = full                    ? "full of " + material
                             : scene.fill.ratio > 0.0 ? fmt::format("r = {:g} {}", scene.fill.ratio, material)
                                                      : std::string("empty");
    r.title = fmt::format("n = {}, {}", scene.shell.sides, fill);
    r.polygon = fmt::format("n = {}", scene.shell.sides);
    r.fill = full                    ? "full of " + material
             : scene.fill.ratio > 0.0 ? fmt::format("{:g} {}", scene.fill.ratio, material)
                                      : std::string("empty");
    const TrajectorySample now = m.trajectory.empty() ? TrajectorySample{} : m.trajectory.back();
    r.time = fmt::format("{:.2f} s", time_s);
    r.position = fmt::format("{:.3f} m", now.position_m);
    // A speed that rounds to zero shows as 0.00, not -0.00.
    r.speed = fmt::format("{:.2f} m/s", std::fabs(now.speed_m_s) < 0.005 ? 0.0 : now.speed_m_s);
    r.impacts = fmt::format("{}", m.impacts.size());
    r.behaviour = behaviour_label(m.behaviour);
    const bool ended = m.behaviour != Behaviour::running;
    r.distance = ended ? fmt::format("{:.3f} m", m.distance_m) : std::string("-");
    r.terminal = m.terminal_velocity_m_s ? fmt::format("{:.3f} m/s", *m.terminal_velocity_m_s) : std::string("-");
    r.model = model_label(scene, choice);
    r.model_reason = choice ? choice->reason : std::string();
    return r;
}

std::string budget_model_label(const Scene& scene, const ModelChoice* choice, const BudgetLevel& level) {
    const ModelLabel l = model_label_parts(scene, choice);
    // The level names the grains ("grains 1.5x larger"): said once, in place of the name of a model
    // with grains that has run from the start, after auto's prefix if any.
    if (l.since.empty() && model_traits(l.running).has_grains) return l.prefix + level_label(level);
    return model_label(scene, choice) + ", " + level_label(level);
}

std::string budget_status(const BudgetLevel& level) {
    return fmt::format("Cheaper model, picked in the panel: {}", level_label(level));
}

std::string status_line(double time_s, const std::string& state, const std::string& speed) {
    const std::string playing = "\u25B6 playing";
    if (state == playing && speed.rfind("playing ", 0) == 0)
        return fmt::format("t = {:.2f} s   \u25B6 {}", time_s, speed);
    return fmt::format("t = {:.2f} s   {}   {}", time_s, state, speed);
}

std::string speed_statement(int slow_divisor, bool stepping, bool keeping_up, double ratio) {
    std::string asked = slow_divisor == 1
                            ? std::string("real time")
                            : fmt::format("1/{}\u00D7 slow motion ({}\u00D7 slower)", slow_divisor, slow_divisor);
    if (!stepping || keeping_up) return asked;
    // Two significant digits: a slow scene reads 0.24x or 0.031x, never 0x. The run is the same on
    // any computer: only how fast it plays depends on this one.
    return fmt::format("playing at {:.2g}\u00D7 real time: this scene costs more than {} here", ratio,
                       slow_divisor == 1 ? asked : fmt::format("1/{}\u00D7 slow motion", slow_divisor));
}

std::string clamp_note(std::string_view label, double typed, double min, double max) {
    if (typed >= min && typed <= max) return "";
    return fmt::format("{} = {:g} is outside {:g} to {:g}: set to {:g}.", label, typed, min, max,
                       std::clamp(typed, min, max));
}

}  // namespace polyroll::app
