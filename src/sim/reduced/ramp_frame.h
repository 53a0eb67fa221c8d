// The ramp and a run's rules, in SI units and the ramp frame of shell_pose.h (x down the slope, y
// along its normal): what the rigid polygon runs on whether it rolls (rolling_polygon.h) or flies and
// slides (free_body.h), built from a scene in one place.
#pragma once

#include <optional>

#include "sim/sample_clock.h"
#include "sim/scene/scene.h"

namespace polyroll::models {

struct RampFrame {
    double angle_deg = 0.0;  // the chord's angle on a curved track
    // The track's shape (ramp_profile.h): 0 is a straight track at angle_deg. The reduced models take
    // the local slope under the contact from it, and book the potential as the track's height.
    double curvature_deg_per_m = 0.0;
    double track_length_m = 0.0;
    double gravity_m_s2 = 0.0;
    // The shell-ramp Coulomb coefficient (Box2D mixes two fixtures' as sqrt(a b); the shell's fixtures
    // carry the ramp's own). The free body slides at it; the rolling polygon checks it only with
    // stop_when_invalid.
    double friction = 0.0;
    double end_centre_x_m = 0.0;  // the run ends when the centre passes this
    double time_limit_s = 0.0;
    double sample_hz = 0.0;  // trajectory rows per second
    // Row times are rounded up to multiples of 1 / this (0: exact multiples of 1 / sample_hz). Set to
    // the grain model's step rate, the rows fall at the times the grain tracker samples.
    double sample_grid_hz = 0.0;
    double rest_speed_m_s = 0.0;  // slower than this: coming to rest
    double rest_time_s = 0.0;     // the rolling polygon's run goes on this long after it stops
    // The rolling polygon's release: its clockwise rotation from face (0, 1) flat (-release angle).
    double start_rotation_rad = 0.0;
    // The rotation (as start_rotation_rad) at which the fill was poured and levelled: the tipped
    // release pours it flat on face (0, 1) and stands shell and pile on the vertex together, turned
    // until the centre of mass of both lies release_tilt_rad past the vertical through the pivot (as
    // the grain model and the 3D reference balance them), in place of start_rotation_rad. None:
    // poured at the release rotation, start_rotation_rad as given.
    std::optional<double> pour_rotation_rad;
    double release_tilt_rad = 0.0;
    // The rolling polygon ends where it stops holding (model_invalid_time_s), its behaviour left
    // "running": for `--model auto`, which hands the shell on there. It then also stops holding where
    // its no-slip rolling needs more friction than `friction` gives (the real shell slips there).
    bool stop_when_invalid = false;

    // The time of trajectory row `row`: the tracker's rule (sample_clock.h) on the sample grid.
    double sample_time(long row) const {
        if (sample_grid_hz <= 0.0) return static_cast<double>(row) / sample_hz;
        return static_cast<double>(first_step_at(row, sample_grid_hz, sample_hz)) / sample_grid_hz;
    }
    // The friction share above which rolling without slipping stops holding; 0: not checked (the
    // reduced models as the experimenters made them).
    double slip_friction() const { return stop_when_invalid ? friction : 0.0; }

    bool curved() const { return curvature_deg_per_m != 0.0; }
    // The local slope (radians) at distance x_m down the track: angle_deg, to the bit, on a straight one.
    double slope_rad_at(double x_m) const;
    // height_m of ramp_profile.h: the potential per unit mass and g of a point x_m down the track and
    // y_m above it.
    double height_at_m(double x_m, double y_m) const;
};

// The scene's ramp, release pose (release_pose() of shell_pose.h) and run rules, rows on the grain
// tracker's sample times.
RampFrame ramp_frame(const Scene& scene);

}  // namespace polyroll::models
