// A whole run shown in tracker steps: see reveal.h.
#include "sim/reduced/reveal.h"

#include <algorithm>

#include "sim/geometry/shell_outline.h"
#include "sim/reveal_steps.h"
#include "sim/run_snapshot.h"

namespace polyroll::models {

RevealedRun::RevealedRun(const Scene& scene, long first_step, Measurements shown)
    : scene_(scene), shown_(std::move(shown)), steps_(first_step) {
    shown_.behaviour = Behaviour::running;
    outer_ = shell_outer_polygon_m(scene.shell);
    inner_ = shell_inner_polygon_m(scene.shell);
}

bool RevealedRun::finished() const { return !stop_step() && time_s() >= whole().end_time_s - 1e-12; }

bool RevealedRun::step() {
    // Past the hand-over step the run has nothing to show: whoever runs it hands the shell over there.
    const std::optional<long> stop = stop_step();
    if (finished() || (stop && steps_ >= *stop)) return false;
    ++steps_;
    reveal();
    return !finished();
}

void RevealedRun::run_to_end() {
    const std::optional<long> stop = stop_step();
    steps_ = stop ? std::max(steps_, *stop) : first_step_at_end(whole().end_time_s, scene_.fidelity.step_hz, steps_);
    reveal();
}

void RevealedRun::reveal() { reveal_up_to(shown_, whole(), time_s(), finished()); }

RunSnapshot RevealedRun::scene_snapshot_now() const { return scene_snapshot(scene_, outer_, inner_); }

}  // namespace polyroll::models
