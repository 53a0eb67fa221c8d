// What an experiment observed, read from an observations file (assets/experiment.json or a lab's own),
// and its expansion into one sweep plan: every observation's scenes, grid, angles and seeds.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/sweep_plan.h"

namespace polyroll::sweep {

struct LinearFit {
    double slope_m_per_deg = 0.0;
    double intercept_m = 0.0;
    std::optional<double> r_squared;
    std::optional<double> distance_uncertainty_m;
};

struct Observation {
    std::string id;
    std::string source;
    nlohmann::ordered_json scene = nlohmann::ordered_json::object();  // field path -> value, flattened
    std::vector<std::pair<std::string, std::vector<nlohmann::ordered_json>>> grid;  // field path -> values
    // Observed: at most one of behaviour and not_behaviour, and at least one of those or a measured number.
    std::string behaviour;      // "rolled_to_end", "stopped", "stopped_at_first_impact" or ""
    std::string not_behaviour;  // a behaviour no run may show, or ""
    std::string terminal_velocity;  // the source's words, reported but not scored
    // Measured numbers (a lab's own file): the mean over the runs must lie within the tolerance.
    std::optional<double> distance_m;             // distance rolled before stopping (or to the end)
    std::optional<double> terminal_velocity_m_s;  // over the last full turn, runs that rolled to the end
    // An angle-range observation: the band where `behaviour` shows, D against theta over it, and the
    // angles to simulate (reaching past both ends, to find them).
    std::optional<std::pair<double, double>> angle_range_deg;
    std::optional<LinearFit> linear_fit;
    std::vector<double> angles_deg;
    // Tolerances.
    double behaviour_share = 1.0;   // least share of runs showing `behaviour` (or not showing not_behaviour)
    double angle_tolerance_deg = 0.0;
    double slope_relative = 0.0;
    double distance_tolerance_m = 0.0;
    double terminal_velocity_tolerance_m_s = 0.0;
    std::string reason;
};

struct ObservationFile {
    std::string origin;  // the file name, or "experiment.json (bundled)"
    nlohmann::ordered_json doc;  // the file as read, for the validation folder's copy
    std::vector<Observation> observations;
    // Named sets of observation ids ("halves": {"fit": [...], "held_back": [...]}): a model fitted on one
    // set is judged on another (assets/reference-3d.json). Each id is the file's, and in one set at most.
    std::vector<std::pair<std::string, std::vector<std::string>>> halves;
};

// Checks and reads an observations document; InputError (one line naming `origin`, the observation
// id, the key, the value and what is allowed) for anything wrong.
ObservationFile parse_observations(const nlohmann::ordered_json& doc, const std::string& origin);
// The bundled assets/experiment.json, or a file on disk.
ObservationFile read_observations(const std::string& path);

// The file with only the observations whose ids are given (in the file's order, each once), its
// document cut to match (what the folder's copy says was scored). An id not in the file is an
// InputError naming it, `flag` and the ids allowed.
ObservationFile only_observations(const ObservationFile& file, const std::vector<std::string>& ids,
                                  const std::string& flag);
// The file with only the observations of its half `name` (--half); InputError naming the halves allowed.
ObservationFile half_of(const ObservationFile& file, const std::string& name);

// One planned run's place: which observation, at which angle (angle-range ones) and grid point.
struct RunPlace {
    std::size_t observation = 0;
    std::size_t run = 0;        // index into the plan
    double angle_deg = 0.0;     // for angle-range observations
    std::uint64_t seed = 0;
    std::string label;          // the grid point, e.g. "shell.preset=octagon-small fill.ratio=0.5"
    // The grid point without its ramp angle: one row of the behaviour map, whose columns are angles.
    std::string label_without_angle;
};

struct ValidationPlan {
    SweepPlan plan;
    std::vector<RunPlace> places;  // one per observation run (a run shared by two observations is listed twice)
};

// The face impact at which everything `ob` scores of a run is known (2: it only asks whether runs
// stop at their first impact, which a second impact decides), or 0: only at the run's own end.
int decided_at_impact(const Observation& ob);

// Every observation's runs: its scene, each grid combination, each angle, seeds 1..seeds, with
// `overrides` (field path -> value, from the command line) on top of each. A run two observations
// share is planned once. Each point is resolved now: a bad value is an InputError naming the observation.
// With `early_exit` (calibrate), a run all of whose observations are decided at a face impact
// (decided_at_impact) ends there: its point sets run.end_at_impact, unless the overrides set it.
ValidationPlan make_validation_plan(const ObservationFile& file, int seeds,
                                   const std::vector<std::pair<std::string, nlohmann::ordered_json>>& overrides,
                                   bool early_exit = false);

}  // namespace polyroll::sweep
