// The sandbox's GL-free logic, without a window: sandbox presets resolve; each panel control changes
// exactly the scene parameters it names and clamps to the valid range; the real-time clock and its
// cap; lanes built, started and stepped together; divergence advice; plot data; pan, zoom and the
// lanes' framing; the scene view's draw list; readouts; exports.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>

#include "app/controls.h"
#include "app/divergence.h"
#include "app/export_files.h"
#include "app/lane_set.h"
#include "app/page_settings.h"
#include "app/plot_data.h"
#include "app/readouts.h"
#include "sim/scene/scene_names.h"
#include "app/sandbox_presets.h"
#include "app/sandbox_settings.h"
#include "app/sandbox_state.h"
#include "app/scene_view.h"
#include "app/sim_clock.h"
#include "app/slider_text.h"
#include "app/text_wrap.h"
#include "app/view_control.h"
#include "render/font.h"
#include "render/ticks.h"
#include "render/world_draw.h"
#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/model_registry.h"
#include "sim/scene/scene_fields.h"
#include "sim/geometry/shell_properties.h"
#include "sim/scene/scene_json.h"
#include "sim/geometry/shell_pose.h"
#include "test_helpers.h"

using namespace polyroll;
using namespace polyroll::app;
using json = nlohmann::ordered_json;
namespace fs = std::filesystem;

namespace {

// The window's scene view at 1280 x 800 beside a 400 px panel, at UI scale 1.
SceneViewOptions window_view_options() {
    SceneViewOptions o;
    o.width_px = 1280;
    o.height_px = 800;
    o.area = {400, 47, 880, 465};
    return o;
}

render::DrawList window_scene_view(const std::vector<render::Snapshot>& snaps) {
    const render::FontAtlas font(render::find_font_dir(), scene_view_fonts(1.0f));
    return build_scene_view(snaps, window_view_options(), font);
}

// "shell.sides" -> value, for every leaf of the resolved scene.
void flatten(const json& j, const std::string& prefix, std::map<std::string, json>& out) {
    if (j.is_object()) {
        for (const auto& [k, v] : j.items()) flatten(v, prefix.empty() ? k : prefix + "." + k, out);
    } else {
        out[prefix] = j;
    }
}

std::map<std::string, json> flat_scene(const Scene& s) {
    std::map<std::string, json> out;
    flatten(scene_to_json(s), "", out);
    return out;
}

// The scene parameters that differ between two scenes.
std::set<std::string> changed_fields(const Scene& a, const Scene& b) {
    const auto fa = flat_scene(a), fb = flat_scene(b);
    std::set<std::string> changed;
    for (const auto& [k, v] : fa)
        if (!fb.count(k) || fb.at(k) != v) changed.insert(k);
    for (const auto& [k, v] : fb)
        if (!fa.count(k)) changed.insert(k);
    return changed;
}

bool all_under(const std::set<std::string>& fields, const std::string& prefix) {
    for (const std::string& f : fields)
        if (f.rfind(prefix, 0) != 0) return false;
    return !fields.empty();
}

struct Base {
    SandboxState state = state_for_preset("default");
    LaneControls& lane() { return state.lanes[0].controls; }
    Scene scene() const { return scenes_for(state).front(); }
};

// A clock that advances by `tick` at every reading, so a budget runs out after a known step count.
struct FakeClock {
    double t = 0.0, tick = 0.0;
    double operator()() { return t += tick; }
};

}  // namespace

TEST_CASE("every sandbox preset resolves to one to four valid lanes", "[app]") {
    const std::vector<std::string> names = sandbox_preset_names();
    REQUIRE(names.size() >= 3);
    CHECK(names.front() == kDefaultSandboxPreset);
    for (const std::string& name : names) {
        INFO(name);
        const SandboxPreset p = sandbox_preset(name);
        CHECK(!p.description.empty());
        const std::vector<Scene> scenes = resolve_preset(p);
        CHECK(scenes.size() >= 1);
        CHECK(static_cast<int>(scenes.size()) <= kMaxLanes);
        // The panel shows each preset exactly: controls read back from the scene rebuild the same scene.
        const SandboxState s = state_for_preset(name);
        const std::vector<Scene> again = scenes_for(s);
        REQUIRE(again.size() == scenes.size());
        CHECK(changed_fields(scenes.front(), again.front()).empty());
    }
    // Presets the docs name as examples.
    for (const char* name : {"octagon-rice", "hexagon-bb", "race"}) CHECK_NOTHROW(sandbox_preset(name));
    const std::vector<Scene> race = resolve_preset(sandbox_preset("race"));
    REQUIRE(race.size() == 3);
    CHECK(race[0].fill.ratio == 0.0);
    CHECK(race[1].fill.ratio == Approx(0.4));
    CHECK(race[2].fill.ratio == 1.0);
    CHECK(resolve_preset(sandbox_preset("default")).front().shell.sides ==
          test::scene_with(json::object()).shell.sides);
    CHECK_THROWS_AS(sandbox_preset("no-such-preset"), InputError);
    CHECK_THROWS_WITH(sandbox_preset("no-such-preset"), Catch::Contains("allowed") && Catch::Contains("race"));
}

TEST_CASE("each panel control changes exactly the scene parameters it names", "[app]") {
    Base b;
    const Scene before = b.scene();
    using Fields = std::set<std::string>;

    SECTION("n") {
        set_control(b.lane(), "shell.sides", 8);
        CHECK(changed_fields(before, b.scene()) == Fields{"shell.sides"});
    }
    SECTION("r") {
        set_control(b.lane(), "fill.ratio", 0.6);
        CHECK(changed_fields(before, b.scene()) == Fields{"fill.ratio"});
    }
    SECTION("theta") {
        set_control(b.state.shared, "ramp.angle_deg", 12.5);
        CHECK(changed_fields(before, b.scene()) == Fields{"ramp.angle_deg"});
        CHECK(b.scene().ramp.angle_deg == 12.5);
    }
    SECTION("material: the grains' values, nothing else") {
        set_material(b.lane(), "rice");
        const Fields f = changed_fields(before, b.scene());
        CHECK(all_under(f, "fill.material."));
        CHECK(f.count("fill.material.preset"));
        CHECK(f.count("fill.material.diameter_m"));
        CHECK(b.scene().fill.material.friction == assets::preset_values(assets::Kind::material, "rice").at("friction").get<double>());
    }
    SECTION("polygon: the shell's values, nothing else") {
        set_control(b.lane(), "shell.preset", "hexagon-large");
        const Fields f = changed_fields(before, b.scene());
        CHECK(all_under(f, "shell."));
        CHECK(f.count("shell.inner_circumradius_m"));
        set_control(b.lane(), "shell.preset", "octagon-small");
        CHECK(b.scene().shell.sides == 8);  // n follows the polygon chosen
    }
    SECTION("ramp: the ramp's values but not the angle") {
        set_control(b.state.shared, "ramp.preset", "wooden");
        const Fields f = changed_fields(before, b.scene());
        CHECK(all_under(f, "ramp."));
        CHECK(f.count("ramp.length_m"));
        CHECK(!f.count("ramp.angle_deg"));
    }
    SECTION("release") {
        set_control(b.state.shared, "release.pose", ReleasePose::face);
        CHECK(changed_fields(before, b.scene()) == Fields{"release.pose"});
    }
    SECTION("model") {
        set_control(b.state.shared, "run.model", Model::rigid);
        CHECK(changed_fields(before, b.scene()) == Fields{"run.model"});
    }
    SECTION("fidelity") {
        set_control(b.state.shared, "fidelity.preset", "precise");
        const Fields f = changed_fields(before, b.scene());
        CHECK(all_under(f, "fidelity."));
        CHECK(f.count("fidelity.preset"));
    }
    SECTION("advanced: friction and restitution") {
        set_control(b.lane(), "fill.material.friction", 0.9);
        CHECK(changed_fields(before, b.scene()) == Fields{"fill.material.friction"});
        Base c;
        set_control(c.lane(), "fill.material.restitution", 0.1);
        CHECK(changed_fields(before, c.scene()) == Fields{"fill.material.restitution"});
        Base d;
        set_control(d.state.shared, "ramp.friction", 0.5);
        CHECK(changed_fields(before, d.scene()) == Fields{"ramp.friction"});
        Base e;
        set_control(e.state.shared, "ramp.restitution", 0.2);
        CHECK(changed_fields(before, e.scene()) == Fields{"ramp.restitution"});
    }
    SECTION("a lane's controls change only that lane") {
        REQUIRE(add_lane(b.state));
        set_control(b.state.lanes[1].controls, "fill.ratio", 0.9);
        const std::vector<Scene> scenes = scenes_for(b.state);
        REQUIRE(scenes.size() == 2);
        CHECK(changed_fields(before, scenes[0]).empty());
        CHECK(changed_fields(before, scenes[1]) == Fields{"fill.ratio"});
    }
}

TEST_CASE("panel values are clamped to their valid range and names are checked", "[app]") {
    LaneControls l = state_for_preset("default").lanes[0].controls;
    SharedControls s = state_for_preset("default").shared;
    set_control(l, "shell.sides", 1);
    CHECK(l.values.shell.sides == scene_field("shell.sides").min);
    set_control(l, "shell.sides", 1000);
    CHECK(l.values.shell.sides == scene_field("shell.sides").max);
    set_control(l, "fill.ratio", -0.5);
    CHECK(l.values.fill.ratio == 0.0);
    set_control(l, "fill.ratio", 1.7);
    CHECK(l.values.fill.ratio == 1.0);
    set_control(l, "fill.ratio", std::numeric_limits<double>::quiet_NaN());
    CHECK(l.values.fill.ratio == 0.0);
    set_control(s, "ramp.angle_deg", 95.0);
    CHECK(s.values.ramp.angle_deg == scene_field("ramp.angle_deg").max);
    set_control(s, "ramp.angle_deg", -3.0);
    CHECK(s.values.ramp.angle_deg == 0.0);
    set_control(l, "fill.material.friction", 5.0);
    CHECK(l.values.fill.material.friction == scene_field("fill.material.friction").max);
    set_control(l, "fill.material.restitution", -1.0);
    CHECK(l.values.fill.material.restitution == 0.0);
    set_control(s, "ramp.friction", -2.0);
    CHECK(s.values.ramp.friction == 0.0);
    set_control(s, "ramp.restitution", 3.0);
    CHECK(s.values.ramp.restitution == 1.0);
    // Clamped values always make a scene the core accepts.
    CHECK_NOTHROW(lane_scene(json::object(), l, s));
    CHECK_THROWS_AS(set_material(l, "sand"), InputError);
    CHECK_THROWS_WITH(set_material(l, "sand"), Catch::Contains("rice"));
    CHECK_THROWS_AS(set_control(l, "shell.preset", "circle"), InputError);
    CHECK_THROWS_AS(set_control(s, "ramp.preset", "ice"), InputError);
    CHECK_THROWS_AS(set_control(s, "fidelity.preset", "ultra"), InputError);
    CHECK_THROWS_AS(model_from("magic"), InputError);
    CHECK(model_from("segments") == Model::segments);
}

TEST_CASE("each panel control is a row naming a labelled field of the scene table", "[app]") {
    std::set<std::string> paths;
    for (const ControlRow& row : control_rows()) {
        INFO(row.path);
        CHECK(paths.insert(std::string(row.path)).second);  // one row per field
        const SceneField& f = scene_field(row.path);          // throws for a path not in the table
        CHECK(!control_label(row).empty());
        if (f.type == FieldType::number || f.type == FieldType::integer) {
            CHECK(!row.format.empty());
            CHECK(f.max > f.min);  // a slider needs fixed limits
            if (row.slider_max) CHECK((*row.slider_max > f.min && *row.slider_max < f.max));
        }
        if (f.type == FieldType::choice)
            for (const RadioOption& o : row.radio) CHECK(f.choice_named(o.name).has_value());
    }
    CHECK_THROWS_AS(control_row("shell.depth_m"), std::logic_error);
    LaneControls l;
    SharedControls s;
    CHECK_THROWS_AS(set_control(l, "ramp.angle_deg", 10.0), std::logic_error);  // a shared row, not a lane's
    CHECK_THROWS_AS(set_control(s, "fill.ratio", 0.5), std::logic_error);
}

TEST_CASE("every panel row names a scene field with a widget and the model combo offers the registry's window models", "[app]") {
    for (const ControlRow& row : control_rows()) {
        INFO(row.path);
        const SceneField& f = scene_field(row.path);  // throws for a row naming no field
        CHECK(f.type != FieldType::optional_number);   // no widget draws one
        CHECK_FALSE(control_label(row).empty());
        if (row.offered) {
            REQUIRE(f.type == FieldType::choice);
            for (const std::string& name : row.offered()) CHECK(f.choice_named(name).has_value());
        }
    }
    const ControlRow& model = control_row("run.model");
    REQUIRE(model.offered != nullptr);
    CHECK(model.offered() == window_model_names());
    CHECK(std::find(model.offered().begin(), model.offered().end(), "dem3d") == model.offered().end());
    // The shared controls hold the model chosen; the lane's are not touched.
    LaneControls lane = state_for_preset("default").lanes[0].controls;
    SharedControls shared = state_for_preset("default").shared;
    const LaneControls lane_before = lane;
    set_control(lane, shared, "run.model", Model::segments);
    CHECK(shared.values.run.model == Model::segments);
    CHECK(lane == lane_before);
}

TEST_CASE("the controls read from a scene give that scene back", "[app]") {
    for (const std::string& name : {std::string("default"), std::string("race")}) {
        const SandboxState st = state_for_preset(name);
        const std::vector<Scene> scenes = scenes_for(st);
        for (size_t i = 0; i < scenes.size(); ++i) {
            const LaneControls l = lane_controls_from(scenes[i]);
            const SharedControls sh = shared_controls_from(scenes[i]);
            CHECK(scene_to_json(lane_scene(st.lanes[i].base, l, sh)) == scene_to_json(scenes[i]));
            for (const ControlRow& row : control_rows()) {
                INFO(row.path);
                CHECK(control_value(row, l, sh) == scene_field(row.path).access.get(scenes[i]));
            }
        }
    }
}

TEST_CASE("lanes: at most four, the last one stays", "[app]") {
    SandboxState s = state_for_preset("default");
    CHECK(!remove_lane(s, 0));
    while (add_lane(s)) {
    }
    CHECK(static_cast<int>(s.lanes.size()) == kMaxLanes);
    CHECK(s.selected_lane == kMaxLanes - 1);
    CHECK(remove_lane(s, 3));
    CHECK(s.lanes.size() == 3);
    CHECK(s.selected_lane == 2);
    // Loading a preset replaces the lanes but keeps the view choices.
    s.follow = true;
    load_preset(s, "race");
    CHECK(s.lanes.size() == 3);
    CHECK(s.follow);
}

TEST_CASE("the clock keeps real time, slows down under its cap and says so", "[app]") {
    SimClock c;
    c.restart(0.0);
    // Real time at 60 frames/s: the target advances by each frame's wall time.
    for (int i = 0; i < 60; ++i) {
        c.advance(1.0 / 60.0);
        c.frame_done(1.0 / 60.0, c.target_s(), false);
    }
    CHECK(c.target_s() == Approx(1.0));
    CHECK(c.realtime_ratio() == Approx(1.0));
    CHECK(c.keeping_up());

    // Slow motion 1/16.
    c.restart(0.0);
    c.set_slow_divisor(16);
    c.advance(1.6);  // a stall counts as at most kMaxFrameDtS
    CHECK(c.target_s() == Approx(kMaxFrameDtS / 16));
    c.set_slow_divisor(1);

    // The budget ran out with half the frame's steps done: the backlog is dropped (no debt builds up)
    // and the clock reports at once that it is not keeping up.
    c.restart(0.0);
    double reached = 0.0;
    for (int i = 0; i < 120; ++i) {
        c.advance(1.0 / 60.0);
        reached += 0.5 / 60.0;
        c.frame_done(1.0 / 60.0, reached, true);
        CHECK(c.target_s() == Approx(reached));
        CHECK(!c.keeping_up());
    }
    CHECK(c.realtime_ratio() == Approx(0.5));
}

TEST_CASE("lanes build in the background, start together and step together within the budget", "[app]") {
    Scene grains = test::scene_with(json::parse(R"({"fill": {"ratio": 0.1}})"));
    Scene rigid = test::scene_with(json::parse(R"({"fill": {"ratio": 0.4}, "run": {"model": "rigid"}})"));
    LaneSet lanes;
    lanes.rebuild({grains, rigid});
    CHECK(!lanes.ready());
    lanes.wait_until_built();
    REQUIRE(lanes.ready());
    REQUIRE(lanes.size() == 2);
    CHECK(lanes.lane(0).time_s() == 0.0);
    CHECK(lanes.lane(1).time_s() == 0.0);
    CHECK(lanes.lane(0).grains() > 0);
    CHECK(lanes.lane(1).grains() == 0);

    // Unlimited budget: both reach the target, in the same fixed steps.
    FakeClock clock;
    AdvanceResult r = lanes.advance_to(0.05, 1e9, std::ref(clock));
    CHECK(!r.budget_hit);
    CHECK(r.steps == 2 * 50);  // 1000 steps/s
    CHECK(lanes.lane(0).time_s() == Approx(0.05));
    CHECK(lanes.lane(1).time_s() == Approx(0.05));
    CHECK(r.reached_s == Approx(0.05));

    // A budget of ten clock ticks: the lanes stop early, side by side.
    clock.tick = 1.0;
    r = lanes.advance_to(1.0, 10.0, std::ref(clock));
    CHECK(r.budget_hit);
    CHECK(r.steps == 2 * 10);
    CHECK(lanes.lane(0).time_s() == Approx(lanes.lane(1).time_s()));

    // Played back, the reduced model reveals its measurements as time passes and ends as run_scene.
    clock.tick = 0.0;
    lanes.advance_to(1e9, 1e9, std::ref(clock));
    CHECK(lanes.all_finished());
    const RunResult full = run_scene(rigid);
    CHECK(lanes.lane(1).measured().behaviour == full.measured.behaviour);
    CHECK(lanes.lane(1).measured().impacts.size() == full.measured.impacts.size());
    CHECK(lanes.lane(0).measured().behaviour != Behaviour::running);
    CHECK(!lanes.trouble());

    // A rebuild throws the old lanes away; bad scenes report their error instead of lanes.
    lanes.rebuild({grains});
    lanes.wait_until_built();
    CHECK(lanes.size() == 1);
}

TEST_CASE("a reduced model's playback turns the polygon on its lowest vertex", "[app]") {
    const Scene s = test::scene_with(json::parse(R"({"run": {"model": "rigid"}})"));
    const ShellPose p0 = rolling_pose(s, 0.0, 0.0);
    const ShellPose release = release_pose(s, shell_properties(s.shell));
    CHECK(p0.angle_rad == Approx(release.angle_rad));
    CHECK(p0.centre_m.x == Approx(release.centre_m.x));
    CHECK(p0.centre_m.y == Approx(release.centre_m.y).margin(1e-9));
    // One face further (360/n degrees) the polygon again rests on a vertex: the centre is at the
    // same height, one side length down the ramp.
    const double side = shell_properties(s.shell).outer_side_m;
    const ShellPose p1 = rolling_pose(s, side, 360.0 / s.shell.sides);
    CHECK(p1.centre_m.y == Approx(p0.centre_m.y).margin(1e-9));
    LaneSet lanes;
    lanes.rebuild({s});
    lanes.wait_until_built();
    const render::Snapshot snap = lanes.lane(0).snapshot();
    CHECK(snapshot_finite(snap));
    CHECK(snap.shell_centre_m.x == Approx(release.centre_m.x));
}

TEST_CASE("numerical trouble stops the lanes with a message and a finer preset to try", "[app]") {
    CHECK(finer_fidelity("draft") == std::optional<std::string>("standard"));
    CHECK(finer_fidelity("standard") == std::optional<std::string>("precise"));
    CHECK(!finer_fidelity("reference"));
    const Scene s = test::scene_with(json::object());
    const std::string m = trouble_message(2, s, 1.5, "grains outside the shell");
    CHECK_THAT(m, Catch::Contains("Lane 2") && Catch::Contains("1.500 s") && Catch::Contains("grains outside") &&
                      Catch::Contains("precise"));
    Scene finest = s;
    finest.fidelity.preset = "reference";
    CHECK_THAT(trouble_message(1, finest, 0.0, "x"), Catch::Contains("finest"));

    render::Snapshot snap;
    CHECK(snapshot_finite(snap));
    snap.grains.push_back({{0.0, std::numeric_limits<double>::quiet_NaN()}, 0.001, 0.0});
    CHECK(!snapshot_finite(snap));

    LaneSet lanes;
    lanes.rebuild({s});
    lanes.wait_until_built();
    lanes.report_non_finite(0);
    REQUIRE(lanes.trouble());
    CHECK_THAT(*lanes.trouble(), Catch::Contains("non-finite"));
    FakeClock clock;
    CHECK(lanes.advance_to(1.0, 1e9, std::ref(clock)).steps == 0);  // paused, not drawing garbage
}

TEST_CASE("plot data: readable ranges, impact markers on the trace, thinning", "[app]") {
    CHECK(render::nice_ceil(0.37, 0.1) == Approx(0.5));
    CHECK(render::nice_ceil(1.2, 1.0) == Approx(2.0));
    CHECK(render::nice_ceil(0.0, 1.0) == Approx(1.0));
    Measurements m;
    for (int i = 0; i <= 100; ++i) {
        TrajectorySample t;
        t.time_s = i * 0.01;
        t.speed_m_s = i <= 50 ? i * 0.01 : -0.02;
        t.kinetic_J = 0.001 * i;
        t.potential_J = -0.002 * i;
        m.trajectory.push_back(t);
    }
    FaceImpact f;
    f.time_s = 0.255;
    m.impacts.push_back(f);
    const PlotRange r = speed_range({&m});
    CHECK(r.t_max_s == Approx(1.0));
    CHECK(r.y_max == Approx(0.5));
    CHECK(r.y_min == Approx(-0.02));
    const PlotRange e = energy_range(m);
    CHECK(e.y_min == Approx(-0.2));
    CHECK(e.y_max == Approx(0.1));
    const std::vector<PlotPoint> marks = impact_markers(m);
    REQUIRE(marks.size() == 1);
    CHECK(marks[0].t_s == 0.255);
    CHECK(marks[0].y == Approx(0.255));
    const std::vector<PlotPoint> thin = series(m, Series::speed, 10);
    CHECK(thin.size() <= 12);
    CHECK(thin.back().t_s == Approx(1.0));  // the latest value is always shown
    CHECK(series(m, Series::potential, 1000).size() == 101);
}

TEST_CASE("pan and zoom keep the point under the mouse where it is, and lanes stack as parallel ramps", "[app]") {
    const render::PxRect area{400, 0, 880, 500};
    render::Camera framed;
    framed.centre_m = {1.0, -0.3};
    framed.anchor = {840, 20};
    framed.px_per_m = 350;
    ViewTransform v;
    const render::Px at{700, 300};
    const geom::Vec2 world{(at.x - framed.anchor.x) / framed.px_per_m + framed.centre_m.x,
                           -(at.y - framed.anchor.y) / framed.px_per_m + framed.centre_m.y};
    v.zoom_at(at, 2.0, area);
    v.zoom_at(at, 1.5, area);
    const render::Px back = v.apply(framed, area).to_px(world);
    CHECK(back.x == Approx(at.x).margin(1e-3));
    CHECK(back.y == Approx(at.y).margin(1e-3));
    CHECK(v.apply(framed, area).px_per_m == Approx(3.0 * 350));
    v.pan_by(10, -5);
    CHECK(v.apply(framed, area).to_px(world).x == Approx(at.x + 10).margin(1e-3));
    v.zoom_at(at, 1e9, area);
    CHECK(v.zoom == kMaxZoom);
    v.reset();
    CHECK(v.zoom == 1.0);

    // Three lanes: one camera each, the same scale, each ramp below the one before.
    Scene s = test::scene_with(json::object());
    LaneSet lanes;
    lanes.rebuild({s, s, s});
    lanes.wait_until_built();
    std::vector<render::Snapshot> snaps;
    for (size_t i = 0; i < 3; ++i) snaps.push_back(lanes.lane(i).snapshot());
    const LaneLayout L = lane_layout(snaps, area, false, 1.0f, ViewTransform{});
    REQUIRE(L.cameras.size() == 3);
    CHECK(L.lane_spacing_px > 0);
    for (size_t i = 1; i < 3; ++i) {
        CHECK(L.cameras[i].px_per_m == L.cameras[0].px_per_m);
        CHECK(L.cameras[i].anchor.y == Approx(L.cameras[0].anchor.y + i * L.lane_spacing_px));
    }
    // Every ramp's lower end is inside the view.
    const render::Px end = L.cameras[2].to_px(render::ramp_to_world({s.ramp.length_m, 0.0}, s.ramp.angle_deg));
    CHECK(end.y <= area.y + area.height);
    CHECK(end.x <= area.x + area.width + 1);
    const LaneLayout F = lane_layout(snaps, area, true, 1.0f, ViewTransform{});
    CHECK(F.cameras[0].px_per_m > L.cameras[0].px_per_m);  // following zooms in
    // The frames' follow framing (render/camera.h): each lane's strip is framed as a frame is.
    CHECK(F.cameras[0].px_per_m * render::outer_radius_m(snaps[0]) ==
          Approx(render::kFollowRadiusShare * area.height / 3.0));
}

TEST_CASE("the scene view draws every lane's shell inside the view, with labels when racing", "[app]") {
    const Scene s = test::scene_with(json::object());
    LaneSet lanes;
    lanes.rebuild({s, s});
    lanes.wait_until_built();
    const SceneViewOptions o = window_view_options();
    const render::DrawList dl = window_scene_view({lanes.lane(0).snapshot(), lanes.lane(1).snapshot()});
    CHECK(dl.width_px == 1280);
    int walls = 0, glyphs = 0;
    for (const render::Layer& l : dl.layers) {
        glyphs += static_cast<int>(l.glyphs.size());
        for (const render::Triangle& t : l.triangles)
            if (t.tag == render::Tag::shell_wall) {
                ++walls;
                for (const render::Px& p : {t.a, t.b, t.c}) {
                    CHECK(p.x >= o.area.x - 1);
                    CHECK(p.y >= o.area.y - 1);
                }
            }
    }
    CHECK(walls >= 3 * 2 * s.shell.sides);  // two lanes and the close-up
    // The scene's text is the frames' (render/view_style.h): the atlas holds those sizes.
    const std::vector<render::FontSpec> fonts = scene_view_fonts(1.0f);
    CHECK(std::count(fonts.begin(), fonts.end(), render::scale_font(1.0f)) == 1);
    CHECK(std::count(fonts.begin(), fonts.end(), render::label_font(1.0f)) == 1);
    CHECK(glyphs > 0);
    CHECK(lane_colour(0) != lane_colour(1));
}

TEST_CASE("the scene view's text stays inside the view: no ramp label behind the panel", "[app]") {
    // The large hexagon full of rice: the tallest clearance, so the ramp is fitted by its height and
    // its labels sit nearest the view's left and right edges.
    const Scene s = test::scene_with(json::parse(R"({"shell": {"preset": "hexagon-large"}})"));
    LaneSet lanes;
    lanes.rebuild({s});
    lanes.wait_until_built();
    for (const float scale : {1.0f, 1.5f, 2.0f}) {
        const render::FontAtlas font(render::find_font_dir(), scene_view_fonts(scale));
        SceneViewOptions o;
        o.width_px = 1280;
        o.height_px = 800;
        o.unit = scale;
        const float panel_w = std::min(400.0f * scale, 640.0f);  // sandbox_ui.cpp's ui_layout
        o.area = {panel_w, 47, 1280 - panel_w, 465};
        const render::DrawList dl = build_scene_view({lanes.lane(0).snapshot()}, o, font);
        // A glyph wholly outside its layer's clip is not drawn; one that is drawn lies wholly inside
        // the clip (no letter cut at an edge) and inside the view (none behind the panel).
        int shown = 0;
        for (const render::Layer& l : dl.layers) {
            const render::ClipRect c = l.clip.value_or(render::ClipRect{0, 0, 1280, 800});
            for (const render::GlyphQuad& g : l.glyphs) {
                const bool outside = g.p1.x <= c.x || g.p0.x >= c.x + c.width || g.p1.y <= c.y || g.p0.y >= c.y + c.height;
                if (outside) continue;
                ++shown;
                INFO("scale " << scale << " glyph at " << g.p0.x << ", " << g.p0.y);
                CHECK(g.p0.x >= std::max<float>(o.area.x, c.x));
                CHECK(g.p1.x <= std::min<float>(o.area.x + o.area.width, c.x + c.width));
                CHECK(g.p0.y >= std::max<float>(o.area.y, c.y));
                CHECK(g.p1.y <= std::min<float>(o.area.y + o.area.height, c.y + c.height));
            }
        }
        CHECK(shown > 0);
    }
}

TEST_CASE("with four lanes the close-up hides no lane's start", "[app]") {
    const Scene s = test::scene_with(json::object());
    LaneSet lanes;
    lanes.rebuild({s, s, s, s});
    lanes.wait_until_built();
    std::vector<render::Snapshot> snaps;
    for (size_t i = 0; i < 4; ++i) snaps.push_back(lanes.lane(i).snapshot());
    const SceneViewOptions o = window_view_options();
    const render::DrawList dl = window_scene_view(snaps);
    // The inset's box: the bounds of its background triangles.
    float top = 1e9f, right = -1e9f;
    for (const render::Layer& l : dl.layers)
        for (const render::Triangle& t : l.triangles)
            if (t.tag == render::Tag::inset_frame)
                for (const render::Px& p : {t.a, t.b, t.c}) {
                    top = std::min(top, p.y);
                    right = std::max(right, p.x);
                }
    REQUIRE(right > o.area.x);
    const LaneLayout L = lane_layout(snaps, o.area, false, 1.0f, ViewTransform{});
    for (size_t i = 0; i < 4; ++i) {
        // Each ramp's first half metre (its start and the "0 m" label under it) is clear of the inset.
        for (const double x_m : {0.0, 0.25, 0.5}) {
            const render::Px p = L.cameras[i].to_px(render::ramp_to_world({x_m, 0.0}, s.ramp.angle_deg));
            INFO("lane " << i + 1 << " at " << x_m << " m: " << p.x << ", " << p.y << "; inset top " << top);
            CHECK((p.x > right || p.y < top));
        }
    }
}

TEST_CASE("readouts say what is known, in SI units", "[app]") {
    const Scene s = test::scene_with(json::parse(R"({"fill": {"ratio": 0.4}})"));
    Measurements m;
    TrajectorySample t;
    t.position_m = 0.1234;
    t.speed_m_s = -0.001;
    m.trajectory.push_back(t);
    LaneReadout r = lane_readout(s, m, 1.5);
    CHECK(r.title == "n = 6, r = 0.4 BBs");
    CHECK(r.time == "1.50 s");
    CHECK(r.position == "0.123 m");
    CHECK(r.speed == "0.00 m/s");
    CHECK(r.behaviour == "rolling");
    CHECK(r.distance == "-");
    m.behaviour = Behaviour::rolled_to_end;
    m.distance_m = 2.4;
    m.terminal_velocity_m_s = 0.61;
    r = lane_readout(s, m, 3.0);
    CHECK(r.distance == "2.400 m");
    CHECK(r.terminal == "0.610 m/s");
    CHECK(r.behaviour == "rolled to the end");
}

TEST_CASE("the model row names the model or what auto chose and when it handed over", "[app]") {
    const Scene s = test::scene_with(json::parse(R"({"fill": {"ratio": 0.0}})"));
    CHECK(lane_readout(s, Measurements{}, 0.0).model == to_string(s.run.model));
    CHECK(lane_readout(s, Measurements{}, 0.0).model_reason.empty());
    ModelChoice c;
    c.model = Model::rigid;
    c.then = Model::grains;
    c.reason = "empty shell";
    LaneReadout r = lane_readout(s, Measurements{}, 0.2, &c);
    CHECK(r.model == "auto: rigid");
    CHECK(r.model_reason == "empty shell");
    c.lift_off_time_s = 0.3;
    CHECK(lane_readout(s, Measurements{}, 0.35, &c).model == "auto: rigid, hops from 0.30 s");
    c.hand_over_time_s = 0.412;
    CHECK(lane_readout(s, Measurements{}, 0.5, &c).model == "auto: grains from 0.41 s");
    ModelChoice filled;
    filled.model = Model::grains;
    CHECK(model_label(s, &filled) == "auto: grains");
}

TEST_CASE("the status line makes one speed statement: the chosen rate, or what the computer reaches", "[app]") {
    CHECK(speed_statement(1, true, true, 1.0) == "real time");
    CHECK(speed_statement(4, true, true, 0.25) == "1/4\u00D7 slow motion (4\u00D7 slower)");
    // Falling behind: the rate reached, with two significant digits, and what was asked; never
    // "real time" beside a lower figure.
    const std::string behind = speed_statement(1, true, false, 0.2412);
    CHECK(behind == "playing at 0.24\u00D7 real time: this scene costs more than real time here");
    CHECK(speed_statement(4, true, false, 0.031) ==
          "playing at 0.031\u00D7 real time: this scene costs more than 1/4\u00D7 slow motion here");
    // Paused or ended: the clock's last verdict no longer applies.
    CHECK(speed_statement(1, false, false, 0.24) == "real time");
    // The line says "playing" once, and a capture claims no rate at all.
    CHECK(status_line(1.2, "\u25B6 playing", behind) ==
          "t = 1.20 s   \u25B6 playing at 0.24\u00D7 real time: this scene costs more than real time here");
    CHECK(status_line(1.2, "\u25B6 playing", "real time") == "t = 1.20 s   \u25B6 playing   real time");
    CHECK(status_line(0.5, "\u275A\u275A paused", "real time") == "t = 0.50 s   \u275A\u275A paused   real time");
    CHECK(std::string(kCaptureSpeedStatement).find("real time") == std::string::npos);
}

TEST_CASE("a value typed outside a control's range is clamped with a note saying so", "[app]") {
    const SceneField& r = scene_field("fill.ratio");
    CHECK(clamp_note(r.label, 50, r.min, r.max) == "r (fill) = 50 is outside 0 to 1: set to 1.");
    CHECK(clamp_note(r.label, -2, r.min, r.max) == "r (fill) = -2 is outside 0 to 1: set to 0.");
    CHECK(clamp_note(r.label, 0.5, r.min, r.max).empty());
    // The control itself keeps the clamped value (controls.h), as the note says.
    LaneControls c;
    set_control(c, "fill.ratio", 50);
    CHECK(c.values.fill.ratio == r.max);
}

TEST_CASE("a slider's value is drawn beside its knob, never under it, and inside its frame", "[app]") {
    // The panel's sliders: about 260 px wide at scale 1, twice that at scale 2, knob 10-20 px.
    for (const float scale : {1.0f, 1.5f, 2.0f}) {
        const float x0 = 8.0f * scale, x1 = x0 + 260.0f * scale;
        const float text_w = 52.0f * scale;  // "20.0\u00B0", "0.00", "1.00\u00D7"
        const float gap = 4.0f * scale;
        for (const int values : {0, 18}) {
            for (int k = 0; k <= 100; ++k) {
                const double fraction = k / 100.0;
                const KnobSpan knob = slider_knob(x0, x1, fraction, 10.0f * scale, values);
                INFO("scale " << scale << " fraction " << fraction << " integer values " << values);
                REQUIRE(knob.min_x >= x0);
                REQUIRE(knob.max_x <= x1);
                const float tx = slider_value_x(x0, x1, knob, text_w, gap);
                const bool beside = tx + text_w <= knob.min_x || tx >= knob.max_x;
                CHECK(beside);
                CHECK(tx >= x0);
                CHECK(tx + text_w <= x1);
            }
        }
    }
    // The knob moves with the value: at the left end, at the right end, and the text changes side.
    const KnobSpan left = slider_knob(0, 200, 0.0, 10), right = slider_knob(0, 200, 1.0, 10);
    CHECK(left.min_x == Approx(2.0f));
    CHECK(right.max_x == Approx(198.0f));
    CHECK(slider_value_x(0, 200, left, 40, 4) > left.max_x);
    CHECK(slider_value_x(0, 200, right, 40, 4) < right.min_x);
    // An integer slider with few values shares the frame among them (ImGui's wider knob).
    const KnobSpan wide = slider_knob(0, 204, 0.5, 10, 4);
    CHECK(wide.max_x - wide.min_x == Approx(50.0f));
}

TEST_CASE("exports write polyroll run's files per lane under numbered names", "[app]") {
    const fs::path dir = fs::temp_directory_path() / "polyroll-app-test-export";
    fs::remove_all(dir);
    fs::create_directories(dir);
    CHECK(next_numbered(dir, "run", "") == dir / "run-001");
    const RunResult r = run_scene(test::scene_with(json::parse(R"({"run": {"model": "rigid"}})")));
    const auto one = export_runs(next_numbered(dir, "run", ""), {r});
    REQUIRE(one.size() == 1);
    CHECK(fs::exists(dir / "run-001" / "summary.json"));
    CHECK(fs::exists(dir / "run-001" / "trajectory.csv"));
    CHECK(fs::exists(dir / "run-001" / "impacts.csv"));
    CHECK(next_numbered(dir, "run", "") == dir / "run-002");
    export_runs(next_numbered(dir, "run", ""), {r, r});
    CHECK(fs::exists(dir / "run-002" / "lane-2" / "trajectory.csv"));
    fs::remove_all(dir);
}

TEST_CASE("the demonstration presets are named for what they show and come first", "[app]") {
    const PresetPanel panel = preset_panel();
    std::vector<std::string> labels;
    for (const PresetButton& b : panel.demos) labels.push_back(b.label);
    CHECK(labels == std::vector<std::string>{"stops at its first impact", "stops abruptly", "rolls to a terminal velocity"});
    // Each says in its description what it shows, and the grid's buttons carry their angle.
    for (const PresetButton& b : panel.demos) CHECK_THAT(b.tooltip, Catch::Contains(b.label));
    REQUIRE(!panel.rows.empty());
    CHECK(panel.rows.front().buttons.front().angle_deg == 20.0);
}

// The rows' heading says "half full"; a button whose preset is not half full says its own fill (the
// large hexagon's rice preset is full).
TEST_CASE("the preset rows say their fill where it is not half full", "[app]") {
    const PresetPanel panel = preset_panel();
    std::map<std::string, std::string> text;  // preset -> button text
    for (const PresetRow& row : panel.rows)
        for (const PresetButton& b : row.buttons) text[b.preset] = row_button_text(b);
    CHECK(text.at("hexagon-bb") == "BBs 20\u00B0");
    CHECK(text.at("hexagon-large-rice") == "rice full 20\u00B0");
    CHECK(preset_rows_heading(panel) == "the experiment's polygons, half full unless the button says:");
    PresetPanel half = panel;
    for (PresetRow& row : half.rows)
        for (PresetButton& b : row.buttons) b.fill_ratio = kRowFillRatio;
    CHECK(preset_rows_heading(half) == "the experiment's polygons, half full:");
    PresetButton third{"p", "BBs", "", 14.0, 0.375};
    CHECK(row_button_text(third) == "BBs r = 0.375 14\u00B0");
}

TEST_CASE("a preset stays lit only while the scene is the preset's, and the polygon box says custom for another n",
          "[app]") {
    SandboxState s = state_for_preset("hexagon-bb");
    CHECK(shows_loaded_preset(s));
    // Flags (and the page's address) over the preset: n, r or theta changed, no preset lit.
    for (const auto& flag : std::vector<std::pair<std::string, std::string>>{{"sides", "8"}, {"fill", "0.375"},
                                                                               {"angle", "14"}}) {
        SandboxState changed = state_for_preset("hexagon-bb");
        apply_page_settings(parse_window_flags({flag}), changed);
        INFO(flag.first);
        CHECK_FALSE(shows_loaded_preset(changed));
    }
    // The same value as the preset's changes nothing; a preset named by the flags is lit.
    SandboxState same = state_for_preset("hexagon-bb");
    apply_page_settings(parse_window_flags({{"sides", "6"}}), same);
    CHECK(shows_loaded_preset(same));
    SandboxState named = state_for_preset("default");
    apply_page_settings(parse_window_flags({{"preset", "octagon-bb"}}), named);
    CHECK(shows_loaded_preset(named));
    // Loading a preset again lights it again.
    s.lanes[0].controls.values.shell.sides = 8;
    CHECK_FALSE(shows_loaded_preset(s));
    load_preset(s, "hexagon-bb");
    CHECK(shows_loaded_preset(s));
    // The polygon box: the preset's name for its own n, "custom" for another.
    CHECK(polygon_combo_text("hexagon-small", 6) == "hexagon-small");
    CHECK(polygon_combo_text("hexagon-small", 8) == "custom (n = 8)");
    CHECK(polygon_combo_text("octagon-small", 8) == "octagon-small");
}

TEST_CASE("the UI scale shown fits the window", "[app]") {
    CHECK(fitted_ui_scale(2.0f, 800, 600) == Approx(1.0f));
    CHECK(fitted_ui_scale(2.0f, 1920, 1080) == Approx(2.0f));
    CHECK(fitted_ui_scale(1.0f, 1280, 800) == Approx(1.0f));
    CHECK(fitted_ui_scale(2.5f, 1280, 800) == Approx(800.0f / kUiScaleWindowHeightPx));
    CHECK(fitted_ui_scale(1.0f, 600, 400) == Approx(kUiScaleMin));
}

TEST_CASE("a scene file gives one lane whose controls rebuild the same scene, and a seed control", "[app]") {
    const std::filesystem::path dir = test::scratch_dir("sandbox-scene-file", true);
    const std::filesystem::path file = dir / "octagon.json";
    std::ofstream(file) << R"({"shell": "octagon-small", "fill": {"ratio": 0.375, "material": "rice"},
                              "ramp": {"angle_deg": 14}, "run": {"seed": 4}})";
    SandboxState s = state_for_scene_file(file.string());
    REQUIRE(s.lanes.size() == 1);
    CHECK(s.preset.empty());
    CHECK(s.scene_file == file.string());
    const Scene scene = scenes_for(s).front();
    CHECK(scene.shell.sides == 8);
    CHECK(scene.fill.ratio == 0.375);
    CHECK(scene.ramp.angle_deg == 14.0);
    CHECK(scene.run.seed == 4);
    set_control(s.shared, "run.seed", 5);
    CHECK(scenes_for(s).front().run.seed == 5);
    CHECK_THROWS_AS(state_for_scene_file((dir / "missing.json").string()), InputError);
    std::filesystem::remove_all(dir);
}

// The panel's prose breaks only at spaces: ImGui's wrapping split "(7.00 s)" after its decimal point.
TEST_CASE("the panel's prose wraps at spaces only, never inside a number", "[app][text]") {
    // One unit per character: the width counts characters.
    const auto chars = [](std::string_view t) { return static_cast<float>(t.size()); };
    const std::string race = "the empty one reaches the end first (7.00 s), the full one 0.3 s later";
    for (float width = 6.0f; width <= 40.0f; width += 1.0f) {
        const std::vector<std::string> lines = polyroll::app::wrap_at_spaces(race, width, chars);
        std::string joined;
        for (const std::string& l : lines) {
            INFO("width " << width << ": '" << l << "'");
            // Each line fits, unless it is one word wider than the width.
            CHECK((l.size() <= width || l.find(' ') == std::string::npos));
            CHECK((l.empty() || (l.front() != ' ' && l.back() != ' ')));
            joined += (joined.empty() ? "" : " ") + l;
        }
        // Nothing lost or split: the lines joined by spaces are the text, and "(7.00" stays whole.
        CHECK(joined == race);
        CHECK(std::any_of(lines.begin(), lines.end(), [](const std::string& l) { return l.find("(7.00") != std::string::npos; }));
    }
    // Line breaks in the text are kept, and an empty text is one empty line.
    CHECK(polyroll::app::wrap_at_spaces("a b\nc", 10.0f, chars) == std::vector<std::string>{"a b", "c"});
    CHECK(polyroll::app::wrap_at_spaces("", 10.0f, chars) == std::vector<std::string>{""});
}
