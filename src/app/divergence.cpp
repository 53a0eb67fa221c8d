// Numerical trouble: see divergence.h.
#include "app/divergence.h"

#include <cmath>

#include <fmt/core.h>

#include "sim/assets.h"

namespace polyroll::app {

std::optional<std::string> finer_fidelity(const std::string& preset) {
    const std::vector<std::string> names = assets::preset_names(assets::Kind::fidelity);
    for (size_t i = 0; i + 1 < names.size(); ++i)
        if (names[i] == preset) return names[i + 1];
    return std::nullopt;
}

std::string trouble_message(int lane_number, const Scene& scene, double time_s, const std::string& why) {
    const std::optional<std::string> finer = finer_fidelity(scene.fidelity.preset);
    const std::string advice =
        finer ? fmt::format("Try the finer fidelity preset '{}' (smaller time step, more solver iterations), then "
                            "Reset.",
                            *finer)
              : std::string("This is already the finest fidelity preset: try a lower ramp angle, a lower fill or "
                            "larger grains, then Reset.");
    return fmt::format("Lane {} stopped at t = {:.3f} s: the simulation went numerically wrong ({}). Paused instead of "
                       "drawing garbage. {}",
                       lane_number, time_s, why, advice);
}

bool snapshot_finite(const render::Snapshot& s) {
    auto ok = [](geom::Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); };
    if (!ok(s.shell_centre_m) || !std::isfinite(s.shell_angle_rad) || !std::isfinite(s.now.speed_m_s) ||
        !std::isfinite(s.now.position_m))
        return false;
    for (const render::GrainState& g : s.grains)
        if (!ok(g.position_m) || !std::isfinite(g.speed_m_s)) return false;
    return true;
}

}  // namespace polyroll::app
