// Calibration: fitting unmeasured scene fields to observations (polyroll calibrate). Each candidate
// (a value per fitted field) is evaluated by running every observation over the same seeds 1..N
// (common random numbers: the packings are the same for every candidate, so differences between
// candidates are the fields' doing) as rows of one sweep folder, scored, and summed into one
// objective that a bounded derivative-free NLopt method minimises. The folder's plan grows by each
// candidate's runs; a deterministic optimiser asks for the same candidates again when the command is
// rerun, and finds their rows done: an interrupted calibration resumes. docs/calibrate.md.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/calibration_params.h"
#include "sweep/observations.h"
#include "sweep/scorecard.h"
#include "sweep/sweep_plan.h"
#include "sweep/sweep_runner.h"

namespace polyroll::sweep {

struct CalibrationSetup {
    ObservationFile file;
    int seeds = 2;
    // A cheaper first pass: the optimiser searches with seeds 1..first_pass_seeds, then its best
    // candidate is evaluated again with seeds 1..seeds (the final pass) and kept if it beats the start
    // there. 0 (or >= seeds): no first pass, every evaluation at `seeds`.
    int first_pass_seeds = 0;
    // ... and in grains this many times larger in diameter, the same fill mass (with_coarser_grains:
    // the window's coarser models, whose cost and errors the trade study measured). 1: the scene's
    // own grains. Either makes a first pass; the final pass is always at the scene's grains.
    double first_pass_grain_scale = 1.0;

    int search_seeds() const { return first_pass_seeds > 0 && first_pass_seeds < seeds ? first_pass_seeds : seeds; }
    double search_grain_scale() const { return first_pass_grain_scale > 1.0 ? first_pass_grain_scale : 1.0; }
    bool has_first_pass() const { return search_seeds() != seeds || search_grain_scale() != 1.0; }
    std::vector<std::pair<std::string, nlohmann::ordered_json>> overrides;  // the command line's, on every run
    std::vector<CalibrationParam> params;
    std::string algorithm = "sbplx";
    int max_evaluations = 24;
};

// The optimisers offered (NLopt's bounded derivative-free local methods), default first.
const std::vector<std::string>& calibration_algorithms();

struct Evaluation {
    std::size_t number = 0;  // 0: the start values (the scene's own)
    std::vector<double> values;
    int seeds = 0;           // seeds 1..seeds: the setup's, or the first pass's
    double grain_scale = 1.0;  // the grains' diameter against the scene's: 1, or the first pass's
    double objective = 0.0;
    std::size_t checks = 0, agreeing = 0;  // scorecard checks, and those that agree
    std::size_t runs = 0, failed = 0;      // the candidate's runs, and the failed ones
    std::size_t ran = 0;                   // run in this session (0: all found done in the folder)
    double wall_time_s = 0.0;
    std::vector<ObservationScore> scores;
};

// The objective: the sum over every check of every observation of its miss squared (in tolerances).
double calibration_objective(const std::vector<ObservationScore>& scores);

// Candidate values as evaluated: 9 significant digits, so that tables and files read cleanly and a
// resumed calibration's candidates are the same text.
double tidy_value(double v);

// A candidate's runs: every observation at seeds 1..seeds with the fitted fields at `values`, and the
// grains `grain_scale` times larger where a run steps grains. With a coarser first pass in the setup,
// the plan also names the fields that make grains coarser, whatever `grain_scale` (a full-detail run
// leaves them out and keeps its id), so that both passes' runs are rows of one folder. Throws
// InputError naming a value that makes a bad scene.
ValidationPlan candidate_plan(const CalibrationSetup& setup, const std::vector<double>& values, int seeds,
                              double grain_scale);

// Thrown when the sweep of a candidate was interrupted (Ctrl-C): rerunning resumes.
struct CalibrationInterrupted : std::runtime_error {
    CalibrationInterrupted() : std::runtime_error("interrupted") {}
};

// The folder's growing plan and the evaluation of candidates on it.
class CalibrationRuns {
public:
    // Runs what is left of a plan in the folder (the command line's: interruptible, parallel).
    // `expected_s`: by plan index, each run's expected wall time (SweepOptions::expected_s).
    using RunPlan = std::function<SweepReport(const SweepPlan&, const std::vector<double>& expected_s)>;
    // Reads the folder's plan.json if there is one (a calibration being resumed). With
    // `wait_for_others` (a shard: run_plan runs one slice), a candidate's runs that other processes
    // run are waited for in the folder's tables, polled every half second; `waiting` is told how
    // many are missing, once per candidate; `stop_requested` ends the wait (CalibrationInterrupted).
    CalibrationRuns(std::filesystem::path dir, const CalibrationSetup& setup, RunPlan run_plan,
                    bool wait_for_others = false, std::function<void(std::size_t)> waiting = {},
                    std::function<bool()> stop_requested = {});

    // The candidate scored over seeds 1..seeds (0: the setup's), its grains `grain_scale` times larger.
    Evaluation evaluate(const std::vector<double>& values, int seeds = 0, double grain_scale = 1.0);
    const SweepPlan& plan() const { return plan_; }

private:
    std::filesystem::path dir_;
    const CalibrationSetup& setup_;
    RunPlan run_plan_;
    SweepPlan plan_;
    std::map<std::string, std::size_t> planned_;  // a point's text -> its index
    // The wall time of each of a candidate's runs (by its place in the candidate's plan) the last time
    // it ran: the next candidate's same runs are expected to take about as long.
    std::map<std::string, double> last_wall_s_;  // by the point without the fitted fields
    std::size_t written_runs_ = 0;                // runs in plan.json on disk
    bool wait_for_others_ = false;
    std::function<void(std::size_t)> waiting_;
    std::function<bool()> stop_requested_;
};

struct CalibrationOutcome {
    std::vector<Evaluation> evaluations;  // [0] the start; then the optimiser's, in order
    std::size_t best = 0;     // the best at the setup's seeds (a first pass's best only once confirmed)
    std::string stop_reason;  // why the optimiser stopped (and, with a first pass, what the final pass found)
};

// Evaluates the start values, then lets the optimiser search within the bounds for at most
// setup.max_evaluations more. `progress` is called after every evaluation with it and the best so far.
// Throws CalibrationInterrupted, InputError, or what an evaluation threw.
CalibrationOutcome run_calibration(const CalibrationSetup& setup, CalibrationRuns& runs,
                                   const std::function<void(const Evaluation&, const Evaluation&)>& progress);

}  // namespace polyroll::sweep
