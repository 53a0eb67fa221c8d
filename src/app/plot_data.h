// The numbers behind the live plots, without any drawing: axis ranges that grow with the data in
// readable steps (render/ticks.h, so the axes do not twitch every frame), the speed at each face
// impact (the plot's markers), the energy series, and thinning a long series to what a plot's width
// can show.
#pragma once

#include <vector>

#include "sim/measurements.h"

namespace polyroll::app {

struct PlotRange {
    double t_max_s = 1.0;
    double y_min = 0.0, y_max = 1.0;
};

// The time axis covers [0, t_max_s] (grown in steps of about an eighth); the value axis includes 0 and every value of every series.
PlotRange speed_range(const std::vector<const Measurements*>& lanes);
PlotRange energy_range(const Measurements& m);

struct PlotPoint {
    double t_s = 0.0;
    double y = 0.0;
};

// The trace of one quantity; `stride` keeps at most `max_points` (the last sample always kept).
enum class Series { speed, kinetic, potential, dissipated };
std::vector<PlotPoint> series(const Measurements& m, Series which, size_t max_points);

// Where each face impact sits on the speed trace (the speed interpolated at its time).
std::vector<PlotPoint> impact_markers(const Measurements& m);

}  // namespace polyroll::app
