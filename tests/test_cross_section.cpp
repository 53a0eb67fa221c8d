// The cross-section study's analysis (sweep/cross_section.h) on a made-up table whose thresholds are
// known: the 3D reference's two degrees below the 2D model's first-impact threshold and sustained
// rolling, for every scene.
#include <catch2/catch.hpp>

#include <string>

#include "sweep/cross_section.h"

using namespace polyroll::sweep;

namespace {

// 2D: stops at its first impact below `first`, rolls to the end from `roll`, stops after rolling
// between; the 3D reference does the same 2.5 and 2 degrees lower (at the matrix's angles).
std::string behaviour(bool is_3d, bool hexagon, double angle) {
    const double first = hexagon ? (is_3d ? 16.0 : 18.0) : (is_3d ? 11.0 : 13.0);
    const double roll = hexagon ? (is_3d ? 18.0 : 20.0) : (is_3d ? 13.0 : 15.0);
    if (angle < first) return "stopped_at_first_impact";
    return angle >= roll ? "rolled_to_end" : "stopped";
}

TableFile made_up_table(const SweepPlan& plan) {
    TableFile t;
    t.header = {"index", "status", "behaviour", "distance_m", "terminal_velocity_m_s", "wall_time_s"};
    for (const PlannedRun& run : plan.runs) {
        const bool is_3d = run.point.at("run.model") == "dem3d";
        const bool hexagon = run.point.at("shell.preset") == "hexagon-small";
        const std::string b = behaviour(is_3d, hexagon, run.point.at("ramp.angle_deg").get<double>());
        const std::string distance = b == "stopped_at_first_impact" ? "0.03" : b == "stopped" ? "1" : "2.54";
        const std::string vt = b == "rolled_to_end" ? (is_3d ? "0.55" : "0.5") : "";
        t.rows.push_back({std::to_string(run.index), "ok", b, distance, vt, is_3d ? "60" : "2"});
    }
    return t;
}

}  // namespace

TEST_CASE("the cross-section analysis reads thresholds, gaps and costs from the table", "[sweep][cross-section]") {
    const SweepPlan plan = cross_section_plan();
    REQUIRE(plan.runs.size() == 2 * 3 * 7 * 2 * 2);  // shells x fills x angles x models x seeds
    const CrossSectionReport rep = analyse_cross_section(plan, made_up_table(plan), "/nonexistent-cross-section");
    const std::string& md = rep.markdown;
    INFO(md);
    // Each scene's row: the interval each threshold lies in, and 3D minus 2D between their midpoints.
    CHECK_THAT(md, Catch::Contains("| n = 6, r = 0.25 | 17-18 | 14-16 | -2.5 | 19-20 | 17-18 | -2.0 | - | - | 0.500 | "
                                   "0.550 | 2.0 | 60.0 |"));
    CHECK_THAT(md, Catch::Contains("| n = 8, r = 0.5 | 12-13 | 9-11 | -2.5 | 14-15 | 12-13 | -2.0 | - | - | 0.500 | "
                                   "0.550 | 2.0 | 60.0 |"));
    // The summary over the six scenes, and the behaviours compared run for run (3 of 7 angles agree).
    CHECK_THAT(md, Catch::Contains("- Same behaviour, run for run (same scene, angle and seed): 36 of 84."));
    CHECK_THAT(md, Catch::Contains("bracketed: -2.5 deg; sustained rolling: -2.0 deg."));
    CHECK_THAT(md, Catch::Contains("- Energy kept at the first impact, 3D minus 2D: -."));
    CHECK_THAT(md, Catch::Contains("- Terminal velocity where both roll to the end, 3D over 2D: +10.0%."));
    CHECK_THAT(md, Catch::Contains("- Cost: 2.0 s a run in 2D, 60.0 s in 3D (30x)."));
    // Every run, by scene and angle.
    CHECK_THAT(md, Catch::Contains("| n = 6, r = 0.25 | 17 | first impact 0.03 | first impact 0.03 | stopped 1.00 | "
                                   "stopped 1.00 |"));
    CHECK_THAT(rep.maps_csv, Catch::StartsWith("shell,sides,fill_ratio,model,angle_deg,seed,behaviour,distance_m,"
                                               "first_impact_kept\n"));
    CHECK_THAT(rep.maps_csv, Catch::Contains("hexagon-small,6,0.25,dem3d,17,1,stopped,1,\n"));
}
