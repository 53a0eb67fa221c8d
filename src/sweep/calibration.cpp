// Calibration on the sweep engine with NLopt: see calibration.h.
#include "sweep/calibration.h"

#include <chrono>
#include <cmath>
#include <exception>
#include <thread>

#include <fmt/core.h>
#include <nlopt.hpp>

#include "sim/errors.h"
#include "sweep/table_scoring.h"

namespace polyroll::sweep {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

const std::vector<std::string>& calibration_algorithms() {
    static const std::vector<std::string> names = {"sbplx", "bobyqa", "cobyla", "neldermead"};
    return names;
}

namespace {

nlopt::algorithm algorithm_of(const std::string& name) {
    if (name == "sbplx") return nlopt::LN_SBPLX;
    if (name == "bobyqa") return nlopt::LN_BOBYQA;
    if (name == "cobyla") return nlopt::LN_COBYLA;
    if (name == "neldermead") return nlopt::LN_NELDERMEAD;
    throw InputError(fmt::format("--algorithm {}: unknown (allowed: sbplx, bobyqa, cobyla, neldermead)", name));
}

std::string result_text(nlopt::result r) {
    switch (r) {
        case nlopt::SUCCESS: return "converged";
        case nlopt::STOPVAL_REACHED: return "objective 0 reached: every check as observed";
        case nlopt::FTOL_REACHED: return "the objective stopped improving (ftol)";
        case nlopt::XTOL_REACHED: return "the step fell below 1/1000 of the bounds (xtol)";
        case nlopt::MAXEVAL_REACHED: return "the evaluation budget (--max-evals) was spent";
        case nlopt::MAXTIME_REACHED: return "time limit";
        default: return fmt::format("nlopt result {}", static_cast<int>(r));
    }
}

}  // namespace

double calibration_objective(const std::vector<ObservationScore>& scores) {
    double sum = 0.0;
    for (const ObservationScore& s : scores)
        for (const ScoreCheck& c : s.checks) sum += c.miss * c.miss;
    return sum;
}

double tidy_value(double v) { return std::stod(fmt::format("{:.9g}", v)); }

CalibrationRuns::CalibrationRuns(fs::path dir, const CalibrationSetup& setup, RunPlan run_plan, bool wait_for_others,
                                 std::function<void(std::size_t)> waiting, std::function<bool()> stop_requested)
    : dir_(std::move(dir)), setup_(setup), run_plan_(std::move(run_plan)), wait_for_others_(wait_for_others),
      waiting_(std::move(waiting)), stop_requested_(std::move(stop_requested)) {
    std::error_code ec;
    if (fs::exists(plan_path(dir_), ec)) {
        plan_ = read_plan(dir_);
        for (const PlannedRun& r : plan_.runs) planned_.emplace(r.point.dump(), r.index);
        written_runs_ = plan_.runs.size();
    }
}

Evaluation CalibrationRuns::evaluate(const std::vector<double>& values) {
    const auto start = std::chrono::steady_clock::now();
    auto overrides = setup_.overrides;
    for (std::size_t i = 0; i < setup_.params.size(); ++i) overrides.emplace_back(setup_.params[i].path, values[i]);
    const ValidationPlan vp = make_validation_plan(setup_.file, setup_.seeds, overrides);
    if (plan_.fields.empty()) {
        plan_.base = vp.plan.base;
        plan_.fields = vp.plan.fields;
        plan_.flags = vp.plan.flags;
    } else if (plan_.fields != vp.plan.fields || plan_.base != vp.plan.base) {
        throw InputError(fmt::format("{}: holds the runs of another calibration (other fields); allowed: a new "
                                     "folder, or --force to start over", plan_path(dir_).string()));
    }
    // The candidate's runs in the folder's plan: ones planned before (the same point) are reused.
    std::vector<std::size_t> table_index;
    for (const PlannedRun& r : vp.plan.runs) {
        const std::string key = r.point.dump();
        auto it = planned_.find(key);
        if (it == planned_.end()) {
            add_run(plan_, r.point);
            it = planned_.emplace(key, plan_.runs.size() - 1).first;
        }
        table_index.push_back(it->second);
    }
    if (plan_.runs.size() != written_runs_) {
        write_plan(dir_, plan_);
        written_runs_ = plan_.runs.size();
    }
    const SweepReport report = run_plan_(plan_);
    if (report.interrupted) throw CalibrationInterrupted();
    auto outcomes = finished_outcomes(plan_, dir_);
    auto missing = [&] {
        std::size_t n = 0;
        for (std::size_t i : table_index) n += outcomes.count(i) ? 0 : 1;
        return n;
    };
    if (wait_for_others_ && missing() > 0) {
        // The other slices are other processes retracing the same path: their rows come.
        if (waiting_) waiting_(missing());
        do {
            if (stop_requested_ && stop_requested_()) throw CalibrationInterrupted();
            std::this_thread::sleep_for(std::chrono::milliseconds(500));
            outcomes = finished_outcomes(plan_, dir_);
        } while (missing() > 0);
    }
    for (std::size_t i : table_index)
        if (!outcomes.count(i))
            throw std::runtime_error(fmt::format("{}: run {} ({}) is missing after the sweep",
                                                 (dir_ / "results.csv").string(), i, plan_.runs[i].id));
    Evaluation e;
    e.values = values;
    e.scores = score_validation(setup_.file, vp, outcomes, table_index);
    e.objective = calibration_objective(e.scores);
    for (const ObservationScore& s : e.scores)
        for (const ScoreCheck& c : s.checks) {
            ++e.checks;
            e.agreeing += c.agree ? 1 : 0;
        }
    e.runs = vp.plan.runs.size();
    for (std::size_t i : table_index) e.failed += outcomes.at(i).ok ? 0 : 1;
    e.ran = report.ran;
    e.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return e;
}

CalibrationOutcome run_calibration(const CalibrationSetup& setup, CalibrationRuns& runs,
                                   const std::function<void(const Evaluation&, const Evaluation&)>& progress) {
    const std::size_t n = setup.params.size();
    CalibrationOutcome out;
    auto record = [&](std::vector<double> x) {
        for (double& v : x) v = tidy_value(v);
        Evaluation e = runs.evaluate(x);
        e.number = out.evaluations.size();
        out.evaluations.push_back(std::move(e));
        const Evaluation& last = out.evaluations.back();
        if (last.objective < out.evaluations[out.best].objective) out.best = last.number;
        if (progress) progress(last, out.evaluations[out.best]);
        return last.objective;
    };
    std::vector<double> x(n), lo(n), hi(n), step(n), xtol(n);
    for (std::size_t i = 0; i < n; ++i) {
        const CalibrationParam& p = setup.params[i];
        x[i] = p.start;
        lo[i] = p.lo;
        hi[i] = p.hi;
        // A quarter of the bounds: the first moves are large enough to leave the seed noise behind.
        step[i] = 0.25 * (p.hi - p.lo);
        xtol[i] = 1e-3 * (p.hi - p.lo);
    }
    record(x);  // the scene's own values: the objective before
    if (setup.max_evaluations <= 0) {
        out.stop_reason = "no optimiser evaluations asked for (--max-evals 0)";
        return out;
    }
    nlopt::opt opt(algorithm_of(setup.algorithm), static_cast<unsigned>(n));
    nlopt::srand(1);  // the local methods used draw no random numbers; fixed anyway, for determinism
    opt.set_lower_bounds(lo);
    opt.set_upper_bounds(hi);
    opt.set_initial_step(step);
    opt.set_xtol_abs(xtol);
    opt.set_maxeval(setup.max_evaluations);
    opt.set_stopval(0.0);
    // NLopt swallows what the objective throws: keep it, stop the optimiser, throw it afterwards.
    std::exception_ptr error;
    struct Context {
        decltype(record)* f;
        std::exception_ptr* error;
        nlopt::opt* opt;
    } ctx{&record, &error, &opt};
    opt.set_min_objective(
        [](const std::vector<double>& v, std::vector<double>&, void* data) {
            auto* c = static_cast<Context*>(data);
            try {
                return (*c->f)(v);
            } catch (...) {
                *c->error = std::current_exception();
                c->opt->force_stop();
                return HUGE_VAL;
            }
        },
        &ctx);
    double f = 0.0;
    nlopt::result r = nlopt::FAILURE;
    try {
        r = opt.optimize(x, f);
    } catch (const nlopt::forced_stop&) {
        if (error) std::rethrow_exception(error);
        throw;
    } catch (const nlopt::roundoff_limited&) {
        r = nlopt::FTOL_REACHED;
    }
    if (error) std::rethrow_exception(error);
    out.stop_reason = result_text(r);
    return out;
}

}  // namespace polyroll::sweep
