// The live plots' data: see plot_data.h.
#include "app/plot_data.h"

#include <algorithm>
#include <cmath>

#include "render/overlay.h"
#include "render/ticks.h"

namespace polyroll::app {

using render::growing_time_axis_s;
using render::growing_value_axis;

namespace {

double value_of(const TrajectorySample& t, Series which) {
    switch (which) {
        case Series::speed: return t.speed_m_s;
        case Series::kinetic: return t.kinetic_J;
        case Series::potential: return t.potential_J;
        case Series::dissipated: return t.dissipated_J;
    }
    return 0.0;
}

double last_time(const Measurements& m) { return m.trajectory.empty() ? 0.0 : m.trajectory.back().time_s; }

}  // namespace

PlotRange speed_range(const std::vector<const Measurements*>& lanes) {
    double t = 0.0, lo = 0.0, hi = 0.0;
    for (const Measurements* m : lanes) {
        t = std::max(t, last_time(*m));
        for (const TrajectorySample& s : m->trajectory) {
            if (!std::isfinite(s.speed_m_s)) continue;
            lo = std::min(lo, s.speed_m_s);
            hi = std::max(hi, s.speed_m_s);
        }
    }
    // The frames' speed plot's axes (render/overlay.h).
    const render::PlotAxes a = render::growing_speed_axes(t, lo, hi);
    return {a.time_max_s, a.speed_min_m_s, a.speed_max_m_s};
}

PlotRange energy_range(const Measurements& m) {
    double lo = 0.0, hi = 0.0;
    for (const TrajectorySample& s : m.trajectory)
        for (double v : {s.kinetic_J, s.potential_J, s.dissipated_J}) {
            if (!std::isfinite(v)) continue;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    PlotRange r;
    r.t_max_s = growing_time_axis_s(last_time(m));
    const render::AxisRange y = growing_value_axis(lo, hi, 0.001, 0.001);  // at least 1 mJ each way
    r.y_min = y.lo;
    r.y_max = y.hi;
    return r;
}

std::vector<PlotPoint> series(const Measurements& m, Series which, size_t max_points) {
    std::vector<PlotPoint> out;
    const size_t n = m.trajectory.size();
    if (n == 0 || max_points == 0) return out;
    const size_t stride = std::max<size_t>(1, (n + max_points - 1) / max_points);
    for (size_t i = 0; i < n; i += stride) out.push_back({m.trajectory[i].time_s, value_of(m.trajectory[i], which)});
    if ((n - 1) % stride != 0) out.push_back({m.trajectory.back().time_s, value_of(m.trajectory.back(), which)});
    return out;
}

std::vector<PlotPoint> impact_markers(const Measurements& m) {
    std::vector<PlotPoint> out;
    const auto& tr = m.trajectory;
    for (const FaceImpact& f : m.impacts) {
        auto it = std::lower_bound(tr.begin(), tr.end(), f.time_s,
                                   [](const TrajectorySample& a, double t) { return a.time_s < t; });
        double v = 0.0;
        if (it == tr.end()) {
            if (tr.empty()) continue;
            v = tr.back().speed_m_s;
        } else if (it == tr.begin() || it->time_s == f.time_s) {
            v = it->speed_m_s;
        } else {
            const TrajectorySample& a = *(it - 1);
            const double w = (f.time_s - a.time_s) / (it->time_s - a.time_s);
            v = a.speed_m_s + w * (it->speed_m_s - a.speed_m_s);
        }
        out.push_back({f.time_s, v});
    }
    return out;
}

}  // namespace polyroll::app
