// Numerical trouble in the sandbox: what to tell the class when a run goes wrong (the tracker's
// divergence message, or a state that is not finite), and what to try instead (a finer fidelity
// preset, or a gentler scene when the finest one is already in use). The window pauses rather than
// draw garbage.
#pragma once

#include <optional>
#include <string>

#include "render/snapshot.h"
#include "sim/measurements.h"
#include "sim/scene/scene.h"

namespace polyroll::app {

// The next finer fidelity preset in assets/fidelity.json's order, if there is one.
std::optional<std::string> finer_fidelity(const std::string& preset);

// One paragraph: which lane, when, why, and the suggestion.
std::string trouble_message(int lane_number, const Scene& scene, double time_s, const std::string& why);

// Every coordinate and speed of the snapshot is finite (a NaN would draw garbage).
bool snapshot_finite(const render::Snapshot& s);

}  // namespace polyroll::app
