// A rigid body sliding on one vertex along a straight ramp with Coulomb friction: the right-hand side
// for the Taylor series integrator (taylor_series.h). With phi the direction of the vertex from the
// centre of mass (in the ramp frame, x down the slope, y along its normal) and R its distance, the
// vertex stays on the ramp (y_c = -R sin phi) and the normal force N, the friction F = f N (f = -+mu,
// against the slip) and the body's motion obey
//   N (1/M + R^2 cos(phi) (cos(phi) - f sin(phi)) / I) = R omega^2 sin(phi) + g cos(theta),
//   phi'' = N R (cos(phi) - f sin(phi)) / I,     x_c'' = g sin(theta) + f N / M,
// an autonomous second-order equation in phi and a quadrature for the centre's x.
#pragma once

#include "sim/reduced/taylor_series.h"

namespace polyroll::models {

struct SlideBody {
    double radius_m = 0.0;          // R: centre of mass to the sliding vertex
    double inv_mass_per_kg = 0.0;   // 1/M
    double inv_inertia = 0.0;       // 1/I about the centre of mass, 1/(kg m^2)
    double friction_ratio = 0.0;    // f = F / N, -+mu against the slip
    double gravity_along_m_s2 = 0.0;   // g sin(theta), down the ramp
    double gravity_normal_m_s2 = 0.0;  // g cos(theta), into the ramp
};

class SlideSeries {
public:
    // The series from phi, omega = phi', the centre's x and its velocity along the ramp.
    SlideSeries(const SlideBody& body, double phi0_rad, double omega0_rad_s, double x0_m, double vx0_m_s);

    struct Point {
        double phi = 0, omega = 0, sin_phi = 0, cos_phi = 0, x_m = 0, vx_m_s = 0;
    };
    Point at(double tau_s) const;
    double accurate_step_s() const { return models::accurate_step_s(phi_); }

private:
    Series phi_{}, omega_{}, sin_{}, cos_{}, x_{}, vx_{};
};

}  // namespace polyroll::models
