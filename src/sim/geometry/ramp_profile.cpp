// The track's shape: see ramp_profile.h.
#include "sim/geometry/ramp_profile.h"

#include <cmath>

namespace polyroll {

namespace {
// Written as every other conversion in sim/ is, so a straight track's gravity is the same to the bit.
double rad(double deg) { return deg * geom::kPi / 180.0; }
double curvature_rad_per_m(const RampParams& ramp) { return rad(ramp.curvature_deg_per_m); }
}  // namespace

double local_slope_deg(const RampParams& ramp, double x_m) {
    // Straight: exactly the angle, whatever x (no rounding added to the scenes that had no profile).
    if (!ramp_is_curved(ramp)) return ramp.angle_deg;
    return ramp.angle_deg + ramp.curvature_deg_per_m * (ramp.length_m / 2.0 - x_m);
}

geom::Vec2 gravity_at_m_s2(const RampParams& ramp, double gravity_m_s2, double x_m) {
    const double slope = rad(local_slope_deg(ramp, x_m));
    return {gravity_m_s2 * std::sin(slope), -gravity_m_s2 * std::cos(slope)};
}

double height_m(const RampParams& ramp, double x_m, double y_m) {
    const double slope = rad(local_slope_deg(ramp, x_m));
    if (!ramp_is_curved(ramp)) return -x_m * std::sin(slope) + y_m * std::cos(slope);
    // The drop from the top to x: the integral of sin(slope) along the track, slope falling linearly.
    const double k = curvature_rad_per_m(ramp);
    const double top = rad(local_slope_deg(ramp, 0.0));
    const double drop_m = (std::cos(slope) - std::cos(top)) / k;
    return -drop_m + y_m * std::cos(slope);
}

double sag_m(const RampParams& ramp) { return curvature_rad_per_m(ramp) * ramp.length_m * ramp.length_m / 8.0; }

double top_slope_deg(const RampParams& ramp) { return local_slope_deg(ramp, 0.0); }
double bottom_slope_deg(const RampParams& ramp) { return local_slope_deg(ramp, ramp.length_m); }

}  // namespace polyroll
