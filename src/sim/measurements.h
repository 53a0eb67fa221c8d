// What a run measures, as the experiment did (docs/physics.md, "What a run measures"), in SI units.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace polyroll {

struct TrajectorySample {
    double time_s = 0.0;
    double position_m = 0.0;   // lid centre along the ramp, from its position at release
    double speed_m_s = 0.0;    // lid centre's velocity along the ramp (negative when rocking back)
    double angle_deg = 0.0;    // shell rotation since release, positive rolling down
    double kinetic_J = 0.0;    // shell and grains
    double potential_J = 0.0;  // shell and grains, relative to release
    double dissipated_J = 0.0; // energy at release minus kinetic minus potential
    // Where the fill's centre of mass sits, from the shell's centre, in the ramp's frame: down the ramp
    // and away from it. Set by the models that move every grain (grains, dem3d), where a fill exists;
    // it shows when the pile flows in the turning shell and when it moves with it as one block.
    std::optional<double> fill_ahead_m;
    std::optional<double> fill_up_m;
};

// When the kinetic energy "after" an impact is read a second time: models with soft contacts (the
// 3D reference's springs last about a millisecond) are still inside the impact at the step the
// tracker sees it end, so their ratios compare with the 2D grains' only when both are read at the same
// delay after the landing. 3 ms covers a 1 ms contact with room; the shell turns about a degree in it.
inline constexpr double kKineticDelay_s = 0.003;

struct FaceImpact {
    int index = 0;  // 1 for the first face landed
    double time_s = 0.0;
    double position_m = 0.0;
    double kinetic_before_J = 0.0;
    double kinetic_after_J = 0.0;
    // At time_s + kKineticDelay_s, for the models stepped in time (grains, dem3d); empty for the
    // models whose impacts are instantaneous, and for an impact the run ended within the delay of.
    std::optional<double> kinetic_delayed_J;
    double ratio() const { return kinetic_before_J > 0.0 ? kinetic_after_J / kinetic_before_J : 0.0; }
};

enum class Behaviour { running, stopped_at_first_impact, stopped, rolled_to_end, time_limit, diverged };
std::string to_string(Behaviour b);

struct Measurements {
    Behaviour behaviour = Behaviour::running;
    std::string divergence;              // what went wrong, when behaviour == diverged
    // Why the run ended before the shell decided its end (run.end_at_impact), or empty. The behaviour is
    // then time_limit: a limit the caller chose ended it.
    std::string ended_early;
    double end_time_s = 0.0;
    double distance_m = 0.0;             // lid centre along the ramp, release to stop or end
    std::optional<double> terminal_velocity_m_s;
    int terminal_velocity_faces = 0;     // how many face intervals the terminal velocity averages
    std::optional<double> stop_time_s;   // when the shell came to rest (start of the rest window)
    double max_energy_gain_J = 0.0;      // largest rise of total energy above its release value
    int grains_inside = 0;               // at the last check
    std::vector<FaceImpact> impacts;
    std::vector<TrajectorySample> trajectory;
};

// Called at every tracker step (of length step_s) after the impact checks: gives each impact its
// kinetic energy at the first step at or past kKineticDelay_s after its landing (kinetic_delayed_J).
void record_delayed_kinetic(Measurements& m, double time_s, double step_s, double kinetic_J);

// The terminal velocity of a run that rolled to the end, as the experiment took it: the mean speed
// of the lid centre over the last full turn (n face intervals, or as many as there were), from the
// impacts' positions and times. Empty with fewer than two impacts. Sets terminal_velocity_faces.
void set_terminal_velocity(Measurements& m, int sides);

// The same for a run that ended at `end` (its last state, in the trajectory or about to be): where
// no face rhythm gives one (fewer than two impacts: a sliding or hopping shell), the mean speed of
// the last tenth of the run from the trajectory.
void set_terminal_velocity_at_end(Measurements& m, int sides, const TrajectorySample& end);

}  // namespace polyroll
