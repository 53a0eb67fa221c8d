// Scoring runs against observations: per observation, what the simulation showed over its seeds,
// whether that agrees with the experiment within the observation's tolerance, and by how much.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/observations.h"

namespace polyroll::sweep {

// One run of an observation as the results table recorded it.
struct ScoredRun {
    double angle_deg = 0.0;   // the run's ramp angle (the simulated angle of an angle-range observation)
    std::uint64_t seed = 0;
    std::string label;        // the grid point
    std::string label_without_angle;  // the grid point but its angle: a row of the behaviour map
    std::string run_id;       // the results table's run_id, for the figures
    double ramp_length_m = 0.0;  // where a run that rolled to the end is drawn in D against theta
    bool ok = false;          // false: failed (invalid point, error, diverged) or missing
    std::string behaviour;    // as in the table: rolled_to_end, stopped, ...
    double distance_m = 0.0;
    std::optional<double> terminal_velocity_m_s;
    double wall_time_s = 0.0;  // what the run cost (calibrate orders the next candidate's runs by it)
};

// One line of the scorecard.
struct ScoreCheck {
    std::string check;       // "behaviour share", "band start", "band end", "D slope", ...
    std::string experiment;  // what the experiment saw, with its tolerance
    std::string simulation;  // what the runs showed, with the seed spread
    bool agree = false;
    std::optional<double> difference;  // simulation minus experiment, in `unit` (none when nothing to compare)
    std::string unit;                  // "share", "deg", "m/deg"
    std::string by;                    // the difference in words: "+2.5 deg, 1.5 beyond the tolerance of 1 deg"
    // How far from the experiment, in tolerances, continuous where the check allows: the calibration's
    // objective sums its squares (docs/calibrate.md). 0 when the simulation is exactly as observed (a
    // share: when it reaches the share); a check with nothing to compare gets a stated penalty.
    double miss = 0.0;
};

struct ObservationScore {
    std::string id;
    std::string source;
    bool agree = false;  // every check agrees
    std::vector<ScoreCheck> checks;
    nlohmann::ordered_json details = nlohmann::ordered_json::object();  // per-angle spread, fits, failures
    // What the experiment saw and its tolerance, as numbers (the checks say it in words), and one
    // entry per run: what the figures (polyroll_figures.py validate) draw, with the results table.
    nlohmann::ordered_json experiment = nlohmann::ordered_json::object();
    nlohmann::ordered_json runs = nlohmann::ordered_json::array();
};

ObservationScore score_observation(const Observation& ob, const std::vector<ScoredRun>& runs);

// Least squares line y = slope x + intercept with R^2; empty with fewer than two distinct x.
struct LineFit {
    double slope = 0.0, intercept = 0.0, r_squared = 0.0;
};
std::optional<LineFit> fit_line(const std::vector<std::pair<double, double>>& xy);

// The scorecard as files: CSV (one row per check) and JSON (every observation with its details).
std::string scorecard_csv(const std::vector<ObservationScore>& scores);
nlohmann::ordered_json scorecard_json(const std::vector<ObservationScore>& scores, const nlohmann::ordered_json& about);
// The table printed on the terminal.
std::string scorecard_text(const std::vector<ObservationScore>& scores);

}  // namespace polyroll::sweep
