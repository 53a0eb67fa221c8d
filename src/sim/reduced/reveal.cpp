// Showing a whole run in tracker steps: see reveal.h.
#include "sim/reduced/reveal.h"

#include <algorithm>
#include <cmath>

#include "sim/geometry/shell_outline.h"
#include "sim/run_snapshot.h"

namespace polyroll::models {

void reveal_up_to(Measurements& shown, const Measurements& whole, double time_s, bool finished) {
    const double t = time_s + 1e-12;
    while (shown.trajectory.size() < whole.trajectory.size() && whole.trajectory[shown.trajectory.size()].time_s <= t)
        shown.trajectory.push_back(whole.trajectory[shown.trajectory.size()]);
    while (shown.impacts.size() < whole.impacts.size() && whole.impacts[shown.impacts.size()].time_s <= t)
        shown.impacts.push_back(whole.impacts[shown.impacts.size()]);
    if (finished) {
        shown = whole;
    } else if (!shown.trajectory.empty()) {
        shown.distance_m = shown.trajectory.back().position_m;
        shown.end_time_s = time_s;
    }
}

long first_step_at_end(double end_time_s, double step_hz, long from_step) {
    const double end = end_time_s - 1e-12;
    if (!std::isfinite(end) || !(step_hz > 0.0)) return from_step;  // never for a validated scene
    long s = std::max(from_step, static_cast<long>(std::ceil(end * step_hz)));
    while (s > from_step && static_cast<double>(s - 1) / step_hz >= end) --s;
    while (static_cast<double>(s) / step_hz < end) ++s;
    return s;
}

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
