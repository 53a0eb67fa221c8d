// Calibration on the sweep engine with NLopt: see calibration.h.
#include "sweep/calibration.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <thread>

#include <fmt/core.h>
#include <nlopt.hpp>

#include "sim/errors.h"
#include "sim/grains/fill_plan.h"
#include "sim/model_registry.h"
#include "sim/scene/scene_json.h"
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

ValidationPlan candidate_plan(const CalibrationSetup& setup, const std::vector<double>& values, int seeds,
                              double grain_scale) {
    auto overrides = setup.overrides;
    for (std::size_t i = 0; i < setup.params.size(); ++i) overrides.emplace_back(setup.params[i].path, values[i]);
    ValidationPlan vp = make_validation_plan(setup.file, seeds, overrides, true);
    if (setup.search_grain_scale() == 1.0) return vp;
    // with_coarser_grains sizes a material's discs by grains_per_disc where it has one, else by the
    // grain diameter: whichever it changed is set in the point.
    static constexpr const char* kGrainsPerDisc = "fill.material.grains_per_disc";
    static constexpr const char* kDiameter = "fill.material.diameter_m";
    SweepPlan plan;
    plan.base = vp.plan.base;
    plan.fields = vp.plan.fields;
    plan.flags = vp.plan.flags;
    for (const char* f : {kGrainsPerDisc, kDiameter})
        if (std::find(plan.fields.begin(), plan.fields.end(), f) == plan.fields.end()) {
            plan.fields.emplace_back(f);
            plan.flags.emplace_back(f);
        }
    for (const PlannedRun& r : vp.plan.runs) {
        json point = r.point;
        const Scene scene = grain_scale == 1.0 ? Scene() : resolve_scene(run_layers(vp.plan, r));
        const bool coarser = grain_scale != 1.0 && may_step_grains(scene);
        if (coarser) {
            const Scene c = with_coarser_grains(scene, grain_scale);
            if (c.fill.material.grains_per_disc)
                point[kGrainsPerDisc] = tidy_value(*c.fill.material.grains_per_disc);
            else
                point[kDiameter] = tidy_value(c.fill.material.diameter_m);
        }
        add_run(plan, std::move(point));
        if (!coarser) continue;
        try {
            resolve_scene(run_layers(plan, plan.runs.back()));
        } catch (const InputError& e) {
            throw InputError(fmt::format("--first-pass-grains {:g}: the coarser grains make a bad scene: {}",
                                         grain_scale, e.what()));
        }
    }
    vp.plan = std::move(plan);
    return vp;
}

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

Evaluation CalibrationRuns::evaluate(const std::vector<double>& values, int seeds, double grain_scale) {
    const auto start = std::chrono::steady_clock::now();
    if (seeds <= 0) seeds = setup_.seeds;
    const ValidationPlan vp = candidate_plan(setup_, values, seeds, grain_scale);
    // A run's place whatever the candidate: its point without the fitted fields.
    std::vector<std::string> slot;
    for (const PlannedRun& r : vp.plan.runs) {
        json p = r.point;
        for (const CalibrationParam& c : setup_.params) p.erase(c.path);
        slot.push_back(p.dump());
    }
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
    std::vector<double> expected;
    if (!last_wall_s_.empty()) {
        expected.assign(plan_.runs.size(), -1.0);
        for (std::size_t j = 0; j < table_index.size(); ++j)
            if (const auto it = last_wall_s_.find(slot[j]); it != last_wall_s_.end()) expected[table_index[j]] = it->second;
    }
    const SweepReport report = run_plan_(plan_, expected);
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
    e.seeds = seeds;
    e.grain_scale = grain_scale;
    e.scores = score_validation(setup_.file, vp, outcomes, table_index);
    e.objective = calibration_objective(e.scores);
    for (const ObservationScore& s : e.scores)
        for (const ScoreCheck& c : s.checks) {
            ++e.checks;
            e.agreeing += c.agree ? 1 : 0;
        }
    e.runs = vp.plan.runs.size();
    for (std::size_t i : table_index) e.failed += outcomes.at(i).ok ? 0 : 1;
    for (std::size_t j = 0; j < table_index.size(); ++j) last_wall_s_[slot[j]] = outcomes.at(table_index[j]).wall_time_s;
    e.ran = report.ran;
    e.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return e;
}

CalibrationOutcome run_calibration(const CalibrationSetup& setup, CalibrationRuns& runs,
                                   const std::function<void(const Evaluation&, const Evaluation&)>& progress) {
    const std::size_t n = setup.params.size();
    const bool first_pass = setup.has_first_pass();
    const int search_seeds = setup.search_seeds();
    const double search_scale = setup.search_grain_scale();
    // Objectives are compared only between evaluations of the same runs: the same seeds and grains.
    auto in_final = [&](const Evaluation& e) { return e.seeds == setup.seeds && e.grain_scale == 1.0; };
    auto in_search = [&](const Evaluation& e) { return e.seeds == search_seeds && e.grain_scale == search_scale; };
    CalibrationOutcome out;
    std::size_t search_best = 0;  // the best of the search's evaluations
    bool searched = false;        // any evaluation of the search's kind yet
    auto evaluate = [&](std::vector<double> x, int seeds, double grain_scale) -> const Evaluation& {
        for (double& v : x) v = tidy_value(v);
        Evaluation e = runs.evaluate(x, seeds, grain_scale);
        e.number = out.evaluations.size();
        out.evaluations.push_back(std::move(e));
        const Evaluation& last = out.evaluations.back();
        if (in_final(last) && last.objective < out.evaluations[out.best].objective) out.best = last.number;
        if (in_search(last) && (!searched || last.objective < out.evaluations[search_best].objective)) {
            search_best = last.number;
            searched = true;
        }
        if (progress) progress(last, out.evaluations[in_search(last) ? search_best : out.best]);
        return last;
    };
    auto record = [&](std::vector<double> x) { return evaluate(std::move(x), search_seeds, search_scale).objective; };
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
    evaluate(x, setup.seeds, 1.0);  // the scene's own values: the objective before
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
    if (first_pass && searched) {
        // The final pass: the search's best at every seed and the scene's grains, kept if it beats the
        // start there.
        const std::vector<double> best_values = out.evaluations[search_best].values;
        const double search_objective = out.evaluations[search_best].objective;
        const std::size_t search_number = search_best;
        const Evaluation& confirmed = evaluate(best_values, setup.seeds, 1.0);
        const Evaluation& before = out.evaluations.front();
        const std::string grains = search_scale == 1.0 ? "" : fmt::format(", grains x{:g}", search_scale);
        out.stop_reason += fmt::format(
            "; first pass at {} seed{}{}: best #{} ({:.4g}); final pass at {} seeds: {:.4g} against {:.4g} for the "
            "start, {}",
            search_seeds, search_seeds == 1 ? "" : "s", grains, search_number, search_objective, setup.seeds,
            confirmed.objective, before.objective,
            out.best == confirmed.number ? "confirmed" : "not confirmed: the start is kept");
    }
    return out;
}

}  // namespace polyroll::sweep
