// Numerical stability at the extremes (ctest label "slow"): n in {3, 4, 6, 18, 64}, r in {0, 0.05,
// 0.5, 0.95, 1}, theta in {0, 2, 30, 60, 85}, at each fidelity preset, with the smallest and the
// largest grains of the bundled materials (rice 3.4 mm, peas 8 mm). Every run must end with finite
// numbers, every grain inside the shell, no energy gained beyond the stated tolerance and a sensible
// behaviour (level ramp: nothing rolls; 85 degrees: nothing stops), or be marked diverged with a
// message that says what to do. The runs go through the sweep engine, two at a time, on the short
// wooden ramp with a short time limit, so the whole matrix stays within minutes.
#include <catch2/catch.hpp>

#include "test_helpers.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "sweep/results_table.h"
#include "sweep/sweep_plan.h"
#include "sweep/sweep_runner.h"

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;
using namespace polyroll;
using namespace polyroll::sweep;

namespace {

// Energy gained above the release value that a run may show and still count as sound: 5% of the
// run's energy scale (total mass x g x pivot radius, the potential energy of one roll over a
// vertex). The tracker itself only calls a run diverged at 50%; a gain between the two is a finding.
constexpr double kEnergyGainShare = 0.05;

struct Matrix {
    std::vector<int> sides;
    std::vector<double> fills;
    std::vector<double> angles;
    std::vector<std::string> materials;
};

// The matrix at one preset as a plan; an empty shell is run once, not once per material.
SweepPlan extremes_plan(const std::string& fidelity, const Matrix& m) {
    SweepPlan plan;
    // The wooden ramp (1.21 m) and 2.5 s: long enough to reach the end at 85 degrees and to settle on
    // a level ramp, short enough for the whole matrix. Slower runs end at the time limit, which is
    // not a fault: the checks on soundness apply to them all the same.
    plan.base = {{"ramp", {{"preset", "wooden"}}},
                 {"fidelity", fidelity},
                 {"run", {{"time_limit_s", 2.5}, {"settle_time_s", 0.5}, {"sample_hz", 60}}}};
    plan.fields = {"shell.sides", "fill.ratio", "ramp.angle_deg", "fill.material.preset"};
    plan.flags = {"sides", "fill", "angle", "material"};
    for (int n : m.sides)
        for (double r : m.fills)
            for (double a : m.angles)
                for (const std::string& mat : m.materials) {
                    if (r == 0.0 && mat != m.materials.front()) continue;
                    add_run(plan, json{{"shell.sides", n}, {"fill.ratio", r}, {"ramp.angle_deg", a},
                                       {"fill.material.preset", mat}});
                }
    return plan;
}

struct Findings {
    int runs = 0, ok = 0, diverged = 0, refused = 0;
    std::map<std::string, int> behaviours;
    std::string diverged_runs;
};

// Runs the plan and checks every run; returns counts for the log.
Findings check_matrix(const std::string& fidelity, const Matrix& m) {
    const SweepPlan plan = extremes_plan(fidelity, m);
    const fs::path dir = fs::temp_directory_path() / ("polyroll-extremes-" + fidelity);
    fs::remove_all(dir);
    SweepOptions o;
    o.dir = dir;
    o.jobs = 2;
    o.trajectories = true;
    o.quiet = true;
    run_sweep(plan, o, nullptr);
    const ResultsTable columns(plan);
    const TableFile t = read_table(dir / "results.csv");
    REQUIRE(t.rows.size() == plan.runs.size());
    auto cell = [&](const std::vector<std::string>& row, const std::string& name) { return row.at(columns.column(name)); };
    Findings f;
    for (const auto& row : t.rows) {
        ++f.runs;
        const std::string what = fidelity + ": n = " + cell(row, "sides") + ", r = " + cell(row, "fill_ratio") +
                                 ", theta = " + cell(row, "angle_deg") + " deg, " + cell(row, "material") + ": " +
                                 cell(row, "behaviour") + " " + cell(row, "reason");
        INFO(what);
        const std::string behaviour = cell(row, "behaviour");
        if (behaviour.empty()) {
            // Refused by validation (e.g. grains too large for the shell): a message naming the value.
            ++f.refused;
            CHECK_THAT(cell(row, "reason"), Catch::StartsWith("invalid point: ") && Catch::Contains("allowed"));
            continue;
        }
        ++f.behaviours[behaviour];
        const fs::path run = dir / "runs" / row.at(1);
        const json summary = json::parse(polyroll::test::read_file(run / "summary.json"));
        const json& res = summary.at("results");
        // No NaN or infinity anywhere in what the run wrote.
        const std::string traj = polyroll::test::read_file(run / "trajectory.csv");
        CHECK(traj.find("nan") == std::string::npos);
        CHECK(traj.find("inf") == std::string::npos);
        CHECK(std::isfinite(res.at("distance_m").get<double>()));
        CHECK(std::isfinite(res.at("max_energy_gain_J").get<double>()));
        if (behaviour == "diverged") {
            // Detected and said: when and why, and what to do about it.
            ++f.diverged;
            f.diverged_runs += "\n  " + what;
            CHECK_THAT(cell(row, "reason"), Catch::Contains("at t = ") && Catch::Contains("use a finer fidelity"));
            continue;
        }
        ++f.ok;
        CHECK(cell(row, "status") == "ok");
        CHECK(cell(row, "grains_inside") == cell(row, "grains"));
        const double mass = summary.at("shell").at("mass_kg").get<double>() + res.at("fill_mass_kg").get<double>();
        const double scale = mass * summary.at("scene").at("run").at("gravity_m_s2").get<double>() *
                             summary.at("shell").at("pivot_radius_m").get<double>();
        CHECK(res.at("max_energy_gain_J").get<double>() <= kEnergyGainShare * scale);
        const double angle = std::stod(cell(row, "angle_deg"));
        const int sides = std::stoi(cell(row, "sides"));
        const double side_m = 2.0 * summary.at("shell").at("outer_circumradius_m").get<double>() * std::sin(M_PI / sides);
        if (angle == 0.0) {
            // A level ramp: the shell tips onto its face and nothing rolls on (a many-sided shell may
            // still be rocking on its face at the short time limit).
            CHECK((behaviour == "stopped_at_first_impact" || behaviour == "time_limit"));
            CHECK(std::fabs(res.at("distance_m").get<double>()) < side_m);
        }
        if (angle == 85.0) CHECK(behaviour == "rolled_to_end");  // nothing stops at 85 degrees
    }
    fs::remove_all(dir);
    return f;
}

void log_findings(const std::string& fidelity, const Findings& f) {
    std::string b;
    for (const auto& [k, v] : f.behaviours) b += " " + k + " " + std::to_string(v);
    WARN(fidelity << ": " << f.runs << " runs, " << f.ok << " sound, " << f.diverged << " diverged (detected), "
                  << f.refused << " refused by validation;" << b << f.diverged_runs);
}

const std::vector<int> kAllSides = {3, 4, 6, 18, 64};
const std::vector<double> kAllFills = {0.0, 0.05, 0.5, 0.95, 1.0};
const std::vector<double> kAllAngles = {0.0, 2.0, 30.0, 60.0, 85.0};
const std::vector<std::string> kGrainSizes = {"rice", "peas"};  // the smallest and largest bundled grains

}  // namespace

TEST_CASE("extremes at draft: the whole matrix", "[slow][extremes]") {
    log_findings("draft", check_matrix("draft", {kAllSides, kAllFills, kAllAngles, kGrainSizes}));
}

TEST_CASE("extremes at standard: the whole matrix", "[slow][extremes]") {
    log_findings("standard", check_matrix("standard", {kAllSides, kAllFills, kAllAngles, kGrainSizes}));
}

TEST_CASE("extremes at precise: the whole matrix", "[slow][extremes]") {
    log_findings("precise", check_matrix("precise", {kAllSides, kAllFills, kAllAngles, kGrainSizes}));
}

// The costliest preset: every n, the fills and angles at the ends of their ranges and one between.
TEST_CASE("extremes at reference: every n, the ends of r and theta", "[slow][extremes]") {
    log_findings("reference", check_matrix("reference", {kAllSides, {0.0, 0.05, 0.5, 1.0}, {0.0, 2.0, 30.0, 85.0},
                                                          kGrainSizes}));
}
