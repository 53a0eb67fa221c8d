// One set of measurement rules (sim/shell_tracker.h): a grain run's states, recorded as the 3D
// reference records its own, measure the same as the run itself; and the rules that differed between
// the two trackers (the rest window, the energy before an impact) on streams made by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "sim/dem3d/state_tracker.h"
#include "sim/files/result_columns.h"
#include "sim/geometry/shell_properties.h"
#include "sim/shell_tracker.h"
#include "sim/grains/tracker.h"
#include "sim/grains/world_builder.h"
#include "hand_landing.h"
#include "test_helpers.h"

using namespace polyroll;
using json = nlohmann::ordered_json;

namespace {

const std::string kStatesHeader =
    "time_s,x_m,y_m,angle_rad,vx_m_s,vy_m_s,omega_rad_s,kinetic_J,potential_J,fill_ahead_m,fill_up_m,grains_inside\n";

// One observed state as a states.csv line, every number to the last bit.
std::string states_line(const ObservedState& s, int grains_inside) {
    const geom::Vec2 fill = s.fill_offset_m.value_or(geom::Vec2{});
    return fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{}\n",
                       s.time_s, s.shell.pose.centre_m.x, s.shell.pose.centre_m.y, s.shell.pose.angle_rad,
                       s.shell.velocity_m_s.x, s.shell.velocity_m_s.y, s.shell.angular_velocity_rad_s, s.kinetic_J,
                       s.potential_J, fill.x, fill.y, grains_inside);
}

struct RecordedRun {
    Measurements measured;
    std::string states_csv;
    dem3d::TrackRules rules;
};

// A grain run to its end, each tracker step's observed state written down as a states.csv row.
RecordedRun record_grain_run(const Scene& scene) {
    Simulation sim(scene);
    const SimWorld& w = sim.world();
    RecordedRun r;
    r.states_csv = kStatesHeader;
    auto record = [&] { r.states_csv += states_line(sim.tracker().observed(), sim.tracker().count_grains_inside()); };
    record();
    while (sim.step()) record();
    record();  // the step that ended the run
    r.measured = sim.measured();
    // The grain model's own rules; measure_states gives the divergences the 3D box's wording.
    r.rules = box2d_track_rules(w);
    return r;
}

// Two rows the same in every column of their file (sim/files/result_columns.h), the column named where
// they differ.
template <class Row>
void check_same_row(std::span<const ResultColumn<Row>> columns, const Row& a, const Row& b) {
    for (const ResultColumn<Row>& c : columns) {
        INFO(c.name);
        CHECK(c.value(a) == c.value(b));
    }
}

void check_same_measurements(const Measurements& a, const Measurements& b) {
    CHECK(to_string(a.behaviour) == to_string(b.behaviour));
    CHECK(a.divergence == b.divergence);
    CHECK(a.end_time_s == b.end_time_s);
    CHECK(a.distance_m == b.distance_m);
    CHECK(a.terminal_velocity_m_s == b.terminal_velocity_m_s);
    CHECK(a.terminal_velocity_faces == b.terminal_velocity_faces);
    CHECK(a.stop_time_s == b.stop_time_s);
    CHECK(a.max_energy_gain_J == b.max_energy_gain_J);
    CHECK(a.grains_inside == b.grains_inside);
    REQUIRE(a.impacts.size() == b.impacts.size());
    for (size_t i = 0; i < a.impacts.size(); ++i) {
        INFO("impact " << i + 1);
        check_same_row(impact_columns(), a.impacts[i], b.impacts[i]);
    }
    REQUIRE(a.trajectory.size() == b.trajectory.size());
    for (size_t i = 0; i < a.trajectory.size(); ++i) {
        INFO("trajectory row " << i);
        check_same_row(trajectory_columns(), a.trajectory[i], b.trajectory[i]);
    }
}

}  // namespace

TEST_CASE("a grain run's states, measured as the 3D reference's rows, give the run's own measurements",
          "[tracker][dem3d]") {
    struct Case {
        const char* what;
        json scene;
        Behaviour expected;
    };
    const std::vector<Case> cases = {
        {"an empty hexagon rolling to the end",
         {{"fill", {{"ratio", 0.0}}}, {"ramp", {{"angle_deg", 10.0}}}},
         Behaviour::rolled_to_end},
        {"an empty hexagon rolling onto the shallow end of a sagging track and stopping there",
         {{"fill", {{"ratio", 0.0}}}, {"ramp", {{"angle_deg", 3.0}, {"curvature_deg_per_m", 10.0}}}},
         Behaviour::stopped},
        {"a filled hexagon stopping at its first impact, its grains counted",
         {{"fill", {{"ratio", 0.25}}}, {"ramp", {{"angle_deg", 14.0}}}},
         Behaviour::stopped_at_first_impact},
        {"a filled hexagon rolling on at the draft fidelity's 240 Hz, to the time limit",
         {{"fill", {{"ratio", 0.2}}}, {"ramp", {{"angle_deg", 22.0}}}, {"fidelity", "draft"},
          {"run", {{"time_limit_s", 0.8}}}},
         Behaviour::time_limit},
    };
    for (const Case& c : cases) {
        INFO(c.what);
        const Scene s = test::scene_with(c.scene);
        const RecordedRun run = record_grain_run(s);
        CHECK(to_string(run.measured.behaviour) == to_string(c.expected));
        const Measurements again = dem3d::measure_states(s, dem3d::parse_states_csv(run.states_csv), run.rules);
        check_same_measurements(run.measured, again);
        CHECK(!run.measured.impacts.empty());
        if (c.expected == Behaviour::rolled_to_end) CHECK(run.measured.terminal_velocity_m_s);
    }
}

namespace {

// A shell standing still on its face but for the first rows, which move at 1 m/s: the rest begins
// at row `moving_rows`.
std::vector<ObservedState> rest_stream(const Scene& s, int rows, int moving_rows) {
    const ShellPose pose = release_pose(s, shell_properties(s.shell));
    std::vector<ObservedState> out;
    for (int k = 0; k < rows; ++k) {
        ObservedState o;
        o.time_s = k / s.fidelity.step_hz;
        o.shell.pose = pose;
        o.shell.velocity_m_s = {k < moving_rows ? 1.0 : 0.0, 0.0};
        out.push_back(o);
    }
    return out;
}

}  // namespace

TEST_CASE("the rest window is held at the rest time even when the times carry a file's rounding", "[tracker]") {
    Scene s = test::scene_with({{"fill", {{"ratio", 0.0}}}, {"fidelity", "standard"}});
    s.fidelity.step_hz = 1000.0;
    s.run.rest_time_s = 0.5;
    // The times as a CSV with millisecond resolution holds them: read back, 0.7 - 0.2 falls short of
    // 0.5 by one rounding, and the run must still stop at 0.7 s, not a step later.
    std::string csv = kStatesHeader;
    for (const ObservedState& o : rest_stream(s, 1000, 200)) {
        std::string line = states_line(o, 0);
        line = fmt::format("{:.3f}", o.time_s) + line.substr(line.find(','));
        csv += line;
    }
    const std::vector<dem3d::StateRow> rows = dem3d::parse_states_csv(csv);
    REQUIRE(rows[700].time_s - rows[200].time_s < 0.5);  // the rounding this rule is for

    dem3d::TrackRules rules;
    rules.energy_scale_J = 1.0;
    rules.contact_tolerance_m = 0.0005;
    const Measurements m = dem3d::measure_states(s, rows, rules);
    REQUIRE(m.behaviour == Behaviour::stopped_at_first_impact);
    REQUIRE(m.stop_time_s);
    CHECK(*m.stop_time_s == rows[200].time_s);
    CHECK(m.end_time_s == rows[700].time_s);

    // The shared tracker itself, fed times k / step_hz: 0.7 - 0.2 falls short of 0.5 the same way.
    ShellTracker direct(s, release_pose(s, shell_properties(s.shell)), rules);
    const std::vector<ObservedState> stream = rest_stream(s, 1000, 200);
    long step = 0;
    while (step < static_cast<long>(stream.size()) && direct.observe(step, stream[static_cast<size_t>(step)])) ++step;
    CHECK(step == 700);
    CHECK(direct.measurements().end_time_s == stream[700].time_s);
}

namespace {

// A hand-made landing (hand_landing.h): rows of height (in contact tolerances), approach speed and
// kinetic energy.
Measurements measure_landing(const Scene& s, const std::vector<test::LandingRow>& rows) {
    return test::measure_landing(s, rows).measured;
}

}  // namespace

TEST_CASE("the energy before an impact is the peak of the approach, from the step before the vertex touched",
          "[tracker]") {
    const Scene s = test::scene_with({{"fill", {{"ratio", 0.0}}}});
    SECTION("a landing the vertex presses into for three steps") {
        const Measurements m = measure_landing(s, {{3.0, 1.0, 1.2},
                                                   {2.0, 1.0, 1.0},    // the last step above the ramp
                                                   {0.5, 1.0, 0.9},    // touching: the springs take energy
                                                   {0.3, 1.0, 0.8},
                                                   {0.1, 1.0, 0.7},
                                                   {0.0, 0.0, 0.5},    // stopped: the impact
                                                   {0.0, 0.0, 0.5}});
        REQUIRE(m.impacts.size() == 1);
        CHECK(m.impacts[0].time_s == 5.0 / s.fidelity.step_hz);
        CHECK(m.impacts[0].kinetic_before_J == 1.0);
        CHECK(m.impacts[0].kinetic_after_J == 0.5);
    }
    SECTION("a vertex falling freely inside the tolerance, as Box2D's does before its contact skin") {
        const Measurements m = measure_landing(s, {{3.0, 1.0, 1.2},
                                                   {2.0, 1.0, 1.0},
                                                   {0.5, 1.0, 1.02},  // touching, still gaining energy
                                                   {0.2, 1.0, 1.04},
                                                   {0.0, 0.0, 0.5},
                                                   {0.0, 0.0, 0.5}});
        REQUIRE(m.impacts.size() == 1);
        CHECK(m.impacts[0].kinetic_before_J == 1.04);
        CHECK(m.impacts[0].kinetic_after_J == 0.5);
    }
    SECTION("a landing stopped in the step it touched") {
        const Measurements m = measure_landing(s, {{3.0, 1.0, 1.2}, {2.0, 1.0, 1.0}, {0.0, 0.0, 0.6}, {0.0, 0.0, 0.6}});
        REQUIRE(m.impacts.size() == 1);
        CHECK(m.impacts[0].kinetic_before_J == 1.0);
        CHECK(m.impacts[0].kinetic_after_J == 0.6);
    }
    SECTION("a touch the vertex leaves again starts the reading afresh") {
        const Measurements m = measure_landing(s, {{3.0, 1.0, 1.2},
                                                   {0.5, 1.0, 1.1},  // touches, then lifts off
                                                   {2.0, 1.0, 1.0},
                                                   {0.5, 1.0, 0.9},
                                                   {0.0, 0.0, 0.4},
                                                   {0.0, 0.0, 0.4}});
        REQUIRE(m.impacts.size() == 1);
        CHECK(m.impacts[0].kinetic_before_J == 1.0);
        CHECK(m.impacts[0].kinetic_after_J == 0.4);
    }
}
