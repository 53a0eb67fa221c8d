// The cross-section study's plan and analysis (sweep/cross_section.h), the analysis on a made-up table
// whose thresholds are known: the 3D reference's two degrees below the 2D model's first-impact
// threshold and sustained rolling for every scene, the 2D model with the closure in between.
#include <catch2/catch.hpp>

#include <initializer_list>
#include <set>
#include <string>

#include "sweep/cross_section.h"
#include "sweep/scene_matrices.h"

using namespace polyroll::sweep;

namespace {

// The closure column's runs: a closure other than none.
bool has_closure(const PlannedRun& run) { return run.point.value("closure.preset", std::string("none")) != "none"; }

// How far below the 2D model's the made-up thresholds of the other columns lie (degrees).
struct Offsets {
    double closure_deg = 1.0;
    double reference_deg = 2.0;
};

// 2D: stops at its first impact below `first`, rolls to the end from `roll`, stops after rolling
// between; the others do the same `Offsets` lower (at the matrix's angles, the 3D reference's gaps come
// out as 2.5 and 2 degrees).
std::string behaviour(const PlannedRun& run, const Offsets& o) {
    const bool hexagon = run.point.at("shell.preset") == "hexagon-small";
    const double offset_deg = run.point.at("run.model") == "dem3d" ? o.reference_deg
                              : has_closure(run)                       ? o.closure_deg
                                                                       : 0.0;
    const double first = (hexagon ? 18.0 : 13.0) - offset_deg;
    const double roll = (hexagon ? 20.0 : 15.0) - offset_deg;
    const double angle = run.point.at("ramp.angle_deg").get<double>();
    if (angle < first) return "stopped_at_first_impact";
    return angle >= roll ? "rolled_to_end" : "stopped";
}

TableFile made_up_table(const SweepPlan& plan, const Offsets& o = {}) {
    TableFile t;
    t.header = {"index", "status", "behaviour", "distance_m", "terminal_velocity_m_s", "wall_time_s"};
    for (const PlannedRun& run : plan.runs) {
        const bool is_3d = run.point.at("run.model") == "dem3d";
        const bool closure = has_closure(run);
        const std::string b = behaviour(run, o);
        const std::string distance = b == "stopped_at_first_impact" ? "0.03" : b == "stopped" ? "1" : "2.54";
        const std::string vt = b != "rolled_to_end" ? "" : is_3d ? "0.55" : closure ? "0.52" : "0.5";
        t.rows.push_back({std::to_string(run.index), "ok", b, distance, vt, is_3d ? "60" : closure ? "3" : "2"});
    }
    return t;
}

void check_contains(const std::string& text, std::initializer_list<const char*> parts) {
    for (const char* part : parts) CHECK_THAT(text, Catch::Contains(part));
}

// The plan as it was before the closure column: 2D and 3D only, no closure.preset field.
SweepPlan two_column_plan(const nlohmann::ordered_json& base) {
    SweepPlan plan;
    plan.base = base;
    plan.fields = {"shell.preset", "fill.ratio", "ramp.angle_deg", "run.model", "run.seed"};
    for (const auto& [shell, angles] : polyroll::scenes::cross_section_shells())
        for (double fill : polyroll::scenes::cross_section_fill_ratios())
            for (double angle : angles)
                for (const std::string model : {"grains", "dem3d"})
                    for (unsigned seed : {1u, 2u})
                        add_run(plan, {{"shell.preset", shell}, {"fill.ratio", fill}, {"ramp.angle_deg", angle},
                                       {"run.model", model}, {"run.seed", seed}});
    return plan;
}

}  // namespace

TEST_CASE("the cross-section plan names each 2D column's closure and keeps the 3D runs' ids",
          "[sweep][cross-section]") {
    const SweepPlan plan = cross_section_plan();
    REQUIRE(plan.runs.size() == 2 * 3 * 7 * 3 * 2);  // shells x fills x angles x columns x seeds
    std::set<std::string> ids;
    int without = 0, with_closure = 0;
    for (const PlannedRun& run : plan.runs) {
        ids.insert(run.id);
        if (run.point.at("run.model") == "dem3d") {
            CHECK_FALSE(run.point.contains("closure.preset"));
            continue;
        }
        // Each 2D run names its closure, so a new default changes neither column.
        REQUIRE(run.point.contains("closure.preset"));
        const std::string closure = run.point.at("closure.preset");
        CHECK((closure == "none" || closure == "pile-bulk"));
        ++(closure == "none" ? without : with_closure);
    }
    CHECK(without == 84);
    CHECK(with_closure == 84);
    CHECK(ids.size() == plan.runs.size());
    // The 3D runs made before the closure columns are the same runs: a folder of them is still theirs.
    const SweepPlan old = two_column_plan(plan.base);
    REQUIRE(old.runs.size() == 168);
    int old_3d = 0;
    for (const PlannedRun& run : old.runs) {
        if (run.point.at("run.model") != "dem3d") continue;
        ++old_3d;
        CHECK(ids.count(run.id) == 1);
    }
    CHECK(old_3d == 84);
}

TEST_CASE("the cross-section analysis reads thresholds, gaps and costs from the table", "[sweep][cross-section]") {
    const SweepPlan plan = cross_section_plan();
    const CrossSectionReport rep = analyse_cross_section(plan, made_up_table(plan), "/nonexistent-cross-section");
    INFO(rep.markdown);
    check_contains(rep.markdown, {
        "**2D**, the grain model at the `standard` preset without a closure",
        "**2D+closure**, the same with the closure `pile-bulk`",
        // Each scene's thresholds (2D, 2D+closure, 3D): the interval each lies in, and 3D minus each 2D
        // column between their midpoints.
        "| scene | first impact 2D (deg) | 2D+closure | 3D | 3D - 2D | 3D - 2D+closure | sustained rolling 2D (deg) | "
        "2D+closure | 3D | 3D - 2D | 3D - 2D+closure |",
        "| n = 6, r = 0.25 | 17-18 | 16-17 | 14-16 | -2.5 | -1.5 | 19-20 | 18-19 | 17-18 | -2.0 | -1.0 |",
        "| n = 8, r = 0.5 | 12-13 | 11-12 | 9-11 | -2.5 | -1.5 | 14-15 | 13-14 | 12-13 | -2.0 | -1.0 |",
        // Energy kept (none: no impacts.csv), Vt and cost, each 2D column paired with the 3D runs.
        "| scene | energy kept at 1st impact 2D / 3D | 2D+closure / 3D | Vt 2D / 3D (m/s) | 2D+closure / 3D | "
        "wall s/run 2D | 2D+closure | 3D |",
        "| n = 6, r = 0.25 | - / - | - / - | 0.500 / 0.550 | 0.520 / 0.550 | 2.0 | 3.0 | 60.0 |",
        // The summary over the six scenes, and the behaviours compared run for run (2D: 3 of 7 angles
        // agree with 3D; 2D+closure: 5 of 7).
        "- Same behaviour as 3D, run for run (same scene, angle and seed): 2D 36 of 84; 2D+closure 60 of 84.\n",
        "bracketed: 2D mean -2.5 deg, |gap| mean 2.5 and worst 2.5 (6 scenes); "
        "2D+closure mean -1.5 deg, |gap| mean 1.5 and worst 1.5 (6 scenes).\n",
        "- Sustained rolling, the same: 2D mean -2.0 deg, |gap| mean 2.0 and worst 2.0 (6 scenes); "
        "2D+closure mean -1.0 deg, |gap| mean 1.0 and worst 1.0 (6 scenes).\n",
        "(|gap| within 0.5 deg on average and 1 at worst): 2D not met; 2D+closure not met.\n",
        "- Energy kept at the first impact, 3D minus the 2D column: 2D -; 2D+closure -.\n",
        "- Terminal velocity where both roll to the end, 3D over the 2D column: 2D +10.0%; 2D+closure +5.8%.\n",
        "- Cost, wall time a run: 3D 60.0 s; 2D 2.0 s (3D 30x); 2D+closure 3.0 s (3D 20x).\n",
        // Every run, by scene and angle: 2D, 2D+closure and 3D, two seeds each.
        "| scene | angle (deg) | 2D seed 1 | 2D seed 2 | 2D+closure seed 1 | 2D+closure seed 2 | 3D seed 1 | "
        "3D seed 2 |",
        "| n = 6, r = 0.25 | 17 | first impact 0.03 | first impact 0.03 | stopped 1.00 | stopped 1.00 | stopped 1.00 | "
        "stopped 1.00 |",
    });
    CHECK_THAT(rep.maps_csv, Catch::StartsWith("shell,sides,fill_ratio,model,angle_deg,seed,behaviour,distance_m,"
                                               "first_impact_kept\n"));
    check_contains(rep.maps_csv, {
        "hexagon-small,6,0.25,dem3d,17,1,stopped,1,\n",
        "hexagon-small,6,0.25,grains+pile-bulk,17,2,stopped,1,\n",
        "hexagon-small,6,0.25,grains,17,1,stopped_at_first_impact,0.03,\n",
    });
}

TEST_CASE("the cross-section summary says which 2D column meets the bar", "[sweep][cross-section]") {
    // The closure column made up to behave as the 3D reference at every angle.
    const SweepPlan plan = cross_section_plan();
    const std::string md =
        analyse_cross_section(plan, made_up_table(plan, {2.0, 2.0}), "/nonexistent-cross-section").markdown;
    INFO(md);
    check_contains(md, {
        "2D 36 of 84; 2D+closure 84 of 84.\n",
        "2D+closure mean +0.0 deg, |gap| mean 0.0 and worst 0.0 (6 scenes).\n",
        "(|gap| within 0.5 deg on average and 1 at worst): 2D not met; 2D+closure met.\n",
    });
}
