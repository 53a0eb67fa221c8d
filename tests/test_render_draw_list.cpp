// The GL-free half of the renderer: a hand-made snapshot's draw list holds the ramp, the shell and
// every grain where the camera puts them; the frame schedule counts frames; the plot and panel fit.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <optional>
#include <vector>

#include "render/changed_regions.h"
#include "render/close_up.h"
#include "render/disc_splat.h"
#include "render/frame_builder.h"
#include "render/frame_schedule.h"
#include "render/overlay.h"
#include "render/render_sequence.h"
#include "render/snapshot.h"
#include "render/ticks.h"
#include "render/world_draw.h"
#include "sim/geometry/disc_size.h"
#include "sim/geometry/geometry.h"
#include "sim/grains/simulation.h"
#include "sim/grains/world_builder.h"
#include "known_snapshot.h"
#include "test_helpers.h"

using namespace polyroll;
using namespace polyroll::render;

namespace {

using test::known_snapshot;

const FontAtlas& atlas_for(const FrameOptions& o) {
    static std::vector<std::unique_ptr<FontAtlas>> keep;
    keep.push_back(std::make_unique<FontAtlas>(find_font_dir(), frame_fonts(o)));
    return *keep.back();
}

std::vector<Shape> shapes_tagged(const Layer& layer, Tag tag) {
    std::vector<Shape> out;
    for (const Shape& s : layer.shapes)
        if (s.tag == tag) out.push_back(s);
    return out;
}

// Pixel position of a ramp-frame point, worked out from the drawn ramp surface alone: its start is
// the ramp's origin, its direction the slope, its length the scale.
struct RampMap {
    Px origin;
    double scale;  // px per m
    double angle_rad;
    Px at(geom::Vec2 p) const {
        const double c = std::cos(angle_rad), s = std::sin(angle_rad);
        // Down the slope goes right and down (y grows downwards in pixels); the normal goes up-right.
        return {static_cast<float>(origin.x + scale * (p.x * c + p.y * s)),
                static_cast<float>(origin.y + scale * (p.x * s - p.y * c))};
    }
};

bool near(Px a, Px b, float tol) { return std::fabs(a.x - b.x) <= tol && std::fabs(a.y - b.y) <= tol; }

}  // namespace

TEST_CASE("the draw list holds the ramp at its angle, the shell and every grain where they are", "[render]") {
    const Snapshot s = known_snapshot();
    FrameOptions o;
    o.width_px = 1280;
    o.height_px = 720;
    const FontAtlas& font = atlas_for(o);
    const DrawList dl = build_frame(s, o, font);
    REQUIRE(dl.width_px == 1280);
    REQUIRE(dl.height_px == 720);
    REQUIRE(!dl.layers.empty());
    const Layer& world = dl.layers.front();  // the main view

    const auto surface = shapes_tagged(world, Tag::ramp_surface);
    REQUIRE(surface.size() == 1);
    const Px a = surface[0].a, b = surface[0].b;
    // The ramp goes down to the right at 30 degrees (pixel y grows downwards).
    CHECK(std::atan2(b.y - a.y, b.x - a.x) == Approx(geom::kPi / 6).margin(1e-4));
    const double scale = std::hypot(b.x - a.x, b.y - a.y) / s.ramp_length_m;
    // The whole ramp fits in the frame, below the overlay panels.
    const FrameLayout L = frame_layout(o);
    for (const Px& p : {a, b}) {
        CHECK(p.x >= 0);
        CHECK(p.x <= 1280);
        CHECK(p.y >= L.panel.y + L.panel.height);
        CHECK(p.y <= 720);
    }
    CHECK(scale > 300.0);  // fills most of the frame's width: 1 m at 30 degrees is 0.87 m wide
    const RampMap map{a, scale, geom::kPi / 6};

    // Every grain, at its place and size.
    const auto grains = shapes_tagged(world, Tag::grain);
    REQUIRE(grains.size() == s.grains.size());
    for (size_t i = 0; i < s.grains.size(); ++i) {
        CHECK(near(grains[i].a, map.at(s.grains[i].position_m), 0.01f));
        CHECK(grains[i].radius == Approx(s.grains[i].radius_m * scale).epsilon(1e-4));
        CHECK(grains[i].fill == material_colour("bb"));
    }

    // The shell's outer edges run between its vertices, turned by its angle about its centre.
    const auto outline = shapes_tagged(world, Tag::shell_outline);
    REQUIRE(outline.size() == 8);  // outer and inner edges
    for (size_t i = 0; i < 4; ++i) {
        const geom::Vec2 v = s.shell_centre_m + geom::rotate(s.outer_local_m[i], s.shell_angle_rad);
        const bool found = std::any_of(outline.begin(), outline.end(),
                                       [&](const Shape& e) { return near(e.a, map.at(v), 0.01f); });
        CHECK(found);
    }
    // The walls fill the band between the polygons; the lid dot sits on the centre.
    const auto walls = std::count_if(world.triangles.begin(), world.triangles.end(),
                                     [](const Triangle& t) { return t.tag == Tag::shell_wall; });
    CHECK(walls == 8);
    const auto dot = shapes_tagged(world, Tag::lid_dot);
    REQUIRE(!dot.empty());
    CHECK(near(dot.back().a, map.at(s.shell_centre_m), 0.01f));
    CHECK(dot.back().fill == palette::lid_dot);

    // A length scale: ticks along the ramp, and the overlay's text is there.
    CHECK(shapes_tagged(world, Tag::ramp_tick).size() >= 10);
    CHECK(!world.glyphs.empty());
    CHECK(!dl.layers.back().glyphs.empty());
}

TEST_CASE("the follow camera keeps the shell in the middle of the view, large", "[render]") {
    Snapshot s = known_snapshot();
    FrameOptions o;
    o.width_px = 640;
    o.height_px = 360;
    o.follow = true;
    const FontAtlas& font = atlas_for(o);
    const FrameLayout L = frame_layout(o);
    CHECK(!L.inset);
    for (double x : {0.1, 0.5, 0.9}) {
        s.shell_centre_m.x = x;
        const DrawList dl = build_frame(s, o, font);
        const auto dot = shapes_tagged(dl.layers.front(), Tag::lid_dot);
        REQUIRE(!dot.empty());
        CHECK(dot.back().a.x == Approx(L.world.x + L.world.width / 2));
        CHECK(dot.back().a.y == Approx(L.world.y + L.world.height / 2));
        // Grains are several pixels across, so a projector shows them.
        for (const Shape& g : shapes_tagged(dl.layers.front(), Tag::grain)) CHECK(g.radius > 3.0f);
    }
}

TEST_CASE("one view layer: the frames' follow framing and styles are the render layer's", "[render]") {
    // The follow framing: the shell's centre in the middle of the area, its outer radius a fixed
    // share of the picture's height, however much of it the overlays take.
    const PxRect area{100.0f, 200.0f, 600.0f, 300.0f};
    const Camera c = follow_framing({0.4, 0.03}, 30.0, 0.05, area, 720.0);
    const Px centre = c.to_px(ramp_to_world({0.4, 0.03}, 30.0));
    CHECK(centre.x == Approx(400.0f));
    CHECK(centre.y == Approx(350.0f));
    CHECK(c.px_per_m * 0.05 == Approx(kFollowRadiusShare * 720.0));

    const Snapshot s = known_snapshot();
    FrameOptions o;
    o.follow = true;
    const FrameLayout L = frame_layout(o);
    CHECK(main_camera(s, o, L).px_per_m * outer_radius_m(s) == Approx(kFollowRadiusShare * o.height_px));

    // The frames' world and close-up are drawn in the shared style at the frame's design pixel.
    const WorldStyle w = world_style(L.unit, area, GrainColouring::speed, 0.7);
    CHECK(w.stroke == L.stroke);
    CHECK(w.scale_font == L.small);
    CHECK(w.grain_colouring == GrainColouring::speed);
    CHECK(w.colour_speed_max_m_s == 0.7);
    const CloseUpStyle cu = close_up_style(area, L.unit);
    CHECK(cu.label_font == L.label);
    CHECK(cu.marker == palette::inset_marker);
}

namespace {

// The bounds of what a draw list holds with one of `tags`: its triangles' corners and its shapes'
// extents (a capsule's ends and radius).
PxRect bounds_tagged(const DrawList& dl, std::initializer_list<Tag> tags) {
    float x0 = 1e9f, y0 = 1e9f, x1 = -1e9f, y1 = -1e9f;
    const auto add = [&](Px p, float r) {
        x0 = std::min(x0, p.x - r), y0 = std::min(y0, p.y - r), x1 = std::max(x1, p.x + r), y1 = std::max(y1, p.y + r);
    };
    const auto tagged = [&](Tag t) { return std::find(tags.begin(), tags.end(), t) != tags.end(); };
    for (const Layer& l : dl.layers) {
        for (const Triangle& t : l.triangles)
            if (tagged(t.tag))
                for (const Px& p : {t.a, t.b, t.c}) add(p, 0.0f);
        for (const Shape& sh : l.shapes)
            if (tagged(sh.tag) && sh.kind == ShapeKind::capsule) {
                add(sh.a, sh.radius);
                add(sh.b, sh.radius);
            }
    }
    return {x0, y0, x1 - x0, y1 - y0};
}

bool overlap(const PxRect& a, const PxRect& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

}  // namespace

// The close-up's label sits inside its top-left corner; in a short inset at a large UI scale (the
// window at 1920x1080 and UI scale 2, racing) the shell is framed below it instead of under it.
TEST_CASE("the close-up's label is clear of the shell, in a tall inset and in a short one", "[render]") {
    const Snapshot s = known_snapshot();
    struct Case {
        PxRect inset;
        float unit;
    };
    for (const Case& c : {Case{{20.0f, 300.0f, 460.0f, 400.0f}, 1.0f}, Case{{824.0f, 525.0f, 403.0f, 142.0f}, 2.0f}}) {
        INFO("inset " << c.inset.width << "x" << c.inset.height << " at unit " << c.unit);
        const PxRect view{0.0f, 0.0f, 1920.0f, 1080.0f};
        const Camera main_cam = whole_ramp_camera(s.ramp_length_m, s.ramp_angle_deg, 0.1, view);
        const WorldStyle w = world_style(c.unit, view, GrainColouring::material, 1.0);
        const FontAtlas font(find_font_dir(), {label_font(c.unit), w.scale_font});
        CloseUpStyle style = close_up_style(c.inset, c.unit);
        style.label_suffix = ", lane 1";
        DrawList dl;
        draw_close_up(s, main_cam, style, w, font, dl);
        // The label: the glyphs of the last layer (the frame's); the shell: its walls and outline.
        PxRect label{dl.layers.back().glyphs.front().p0.x, dl.layers.back().glyphs.front().p0.y, 0.0f, 0.0f};
        float right = label.x, bottom = label.y;
        for (const GlyphQuad& g : dl.layers.back().glyphs) {
            label.x = std::min(label.x, g.p0.x);
            label.y = std::min(label.y, g.p0.y);
            right = std::max(right, g.p1.x);
            bottom = std::max(bottom, g.p1.y);
        }
        label.width = right - label.x;
        label.height = bottom - label.y;
        const PxRect shell = bounds_tagged(dl, {Tag::shell_inside, Tag::shell_wall, Tag::shell_outline});
        INFO("label " << label.x << "," << label.y << " " << label.width << "x" << label.height << "; shell " << shell.x
                      << "," << shell.y << " " << shell.width << "x" << shell.height);
        REQUIRE(shell.width > 0.0f);
        CHECK_FALSE(overlap(label, shell));
        // The shell whole inside the inset.
        CHECK(shell.y >= c.inset.y);
        CHECK(shell.y + shell.height <= c.inset.y + c.inset.height);
    }
}

TEST_CASE("grains coloured by speed follow the colour map", "[render]") {
    const Snapshot s = known_snapshot();
    FrameOptions o;
    o.width_px = 640;
    o.height_px = 360;
    o.grain_colouring = GrainColouring::speed;
    o.colour_speed_max_m_s = 0.4;
    const DrawList dl = build_frame(s, o, atlas_for(o));
    const auto grains = shapes_tagged(dl.layers.front(), Tag::grain);
    REQUIRE(grains.size() == 3);
    CHECK(grains[0].fill == speed_colour(0.25));
    CHECK(grains[2].fill == speed_colour(0.75));
    CHECK(!(grains[0].fill == grains[2].fill));
}

TEST_CASE("the speed plot's axes cover the data and grow with it", "[render]") {
    Snapshot s = known_snapshot();
    FrameOptions o;
    PlotAxes ax = plot_axes(s, o);
    CHECK(ax.time_max_s >= 0.5);
    CHECK(ax.speed_max_m_s >= 0.42);
    CHECK(ax.speed_min_m_s == 0.0);
    s.speed_history.push_back({3.2, -0.15});
    ax = plot_axes(s, o);
    CHECK(ax.time_max_s >= 3.2);
    CHECK(ax.speed_min_m_s <= -0.15);
    o.plot_time_max_s = 10.0;
    CHECK(plot_axes(s, o).time_max_s == 10.0);
}

TEST_CASE("readable numbers: nice values, axis ends and ticks, the same for frames and window", "[render]") {
    CHECK(nice_ceil(0.37) == Approx(0.5));
    CHECK(nice_ceil(2.0) == 2.0);  // already nice: not a step up
    CHECK(nice_ceil(0.0) == 1.0);
    CHECK(nice_ceil(std::nan("")) == 1.0);
    CHECK(nice_ceil(0.001, 0.1) == Approx(0.1));
    CHECK(nice_ceil(std::numeric_limits<double>::infinity(), 0.1) == 0.1);
    CHECK(round_up_nice(1.225, 5.0) == Approx(1.5));
    CHECK(round_up_nice(11.4, 8.0) == Approx(12.0));
    CHECK(round_up_nice(-1.0, 5.0) == 0.0);

    // Growing axes (the frames' plot without fixed axes, the window's plots).
    CHECK(growing_time_axis_s(0.3) == 1.0);
    CHECK(growing_time_axis_s(11.4) == Approx(12.0));
    const AxisRange grown = growing_value_axis(-0.013, 0.37, kSpeedAxisFloor_m_s, kSpeedAxisFloorBelow_m_s);
    CHECK(grown.lo == Approx(-0.02));
    CHECK(grown.hi == Approx(0.5));
    CHECK(growing_value_axis(0.0, 0.01, 0.1, 0.01).lo == 0.0);

    // A speed axis from -0.15 to 0.5: steps of 0.2 from 0 (a +0 that prints "0", never "-0").
    const AxisTicks v = axis_ticks(-0.15, 0.5, 4.0);
    CHECK(v.step == Approx(0.2));
    CHECK(v.first == Approx(0.0));
    CHECK(!std::signbit(v.first));
    CHECK(v.count == 3);
    CHECK(v.at(v.count - 1) <= 0.5);
    const AxisTicks t = axis_ticks(0.0, 2.5, 5.0);
    CHECK(t.step == Approx(0.5));
    CHECK(t.count == 6);
    CHECK(!std::signbit(t.at(0)));
    // No range, no ticks; never an endless axis.
    CHECK(axis_ticks(0.0, std::nan(""), 4.0).count == 0);
    CHECK(axis_ticks(0.0, std::numeric_limits<double>::infinity(), 4.0).count == 0);
    CHECK(axis_ticks(0.0, 1e9, 1e9).count == kMaxTicks);
}

TEST_CASE("the frame schedule takes a frame whenever simulated time advances by 1/(fps x slow)", "[render]") {
    const FrameSchedule f{30.0, 1, 1000.0, 1.0};
    CHECK(f.step_for_frame(0) == 0);
    CHECK(f.step_for_frame(1) == 34);  // 33.3 steps: the first step at or after 1/30 s
    CHECK(f.step_for_frame(3) == 100);
    CHECK(f.run_frames(1000) == 31);   // 0, 1/30, ..., 1 s
    CHECK(f.run_frames(999) == 30);
    CHECK(f.hold_frames() == 30);
    CHECK(f.total_frames(1000) == 61);
    const FrameSchedule slow{60.0, 4, 1000.0, 0.5};
    CHECK(slow.run_frames(1000) == 241);
    CHECK(slow.hold_frames() == 30);
    // The count and the steps agree at every length: the last frame is inside the run, the next is not.
    for (const FrameSchedule& g : {f, slow, FrameSchedule{24.0, 3, 240.0, 0.0}, FrameSchedule{29.97, 1, 1000.0, 0.0}})
        for (long end = 0; end < 3000; end += 7) {
            const long n = g.run_frames(end);
            CHECK(g.step_for_frame(n - 1) <= end);
            CHECK(g.step_for_frame(n) > end);
        }
}

TEST_CASE("a snapshot copies the simulation's state in metres", "[render]") {
    const Scene scene = test::scene_with({{"run", {{"time_limit_s", 0.05}}}});
    Simulation sim(scene);
    while (sim.step()) {
    }
    const Snapshot s = sim.snapshot();
    const SimWorld& w = sim.world();
    CHECK(s.sides == scene.shell.sides);
    CHECK(s.grains.size() == w.grains.size());
    CHECK(s.shell_centre_m.x == Approx(w.units.to_m(w.shell->GetPosition().x)));
    // The shell rests on the ramp: its centre is about an apothem above the surface, in metres.
    CHECK(s.shell_centre_m.y > 0.02);
    CHECK(s.shell_centre_m.y < 0.06);
    for (const GrainState& g : s.grains) {
        CHECK(geom::length(g.position_m - s.shell_centre_m) < 0.04);
        CHECK(g.radius_m == Approx(disc_diameter_m(scene) / 2).epsilon(0.05));
    }
    CHECK(s.time_s == Approx(0.05));
    CHECK(s.speed_history.back().time_s == Approx(s.time_s));
}

namespace {
int glyph_count(const DrawList& dl) {
    int n = 0;
    for (const Layer& l : dl.layers) n += static_cast<int>(l.glyphs.size());
    return n;
}
}  // namespace

TEST_CASE("a frame says the run's outcome at the end and marks slow motion", "[render]") {
    Measurements m;
    m.behaviour = Behaviour::stopped;
    m.distance_m = 0.14;
    CHECK(outcome_text(m) == "stopped after 0.14 m");
    m.behaviour = Behaviour::rolled_to_end;
    m.distance_m = 2.5;
    CHECK(outcome_text(m) == "rolled to the end (2.50 m)");
    m.behaviour = Behaviour::running;
    CHECK(outcome_text(m).empty());

    const Snapshot s = known_snapshot();
    FrameOptions o;
    const FontAtlas& font = atlas_for(o);
    const int plain = glyph_count(build_frame(s, o, font));
    // The banner: its letters (spaces aside) added, every one inside the frame and below the
    // panel and the plot, so it hides neither.
    FrameOptions ended = o;
    ended.outcome = "stopped after 0.14 m";
    const DrawList with_banner = build_frame(s, ended, font);
    CHECK(glyph_count(with_banner) == plain + 17);
    const FrameLayout L = frame_layout(ended);
    const Layer& overlay = with_banner.layers.back();
    REQUIRE(overlay.glyphs.size() >= 17);
    for (size_t i = overlay.glyphs.size() - 17; i < overlay.glyphs.size(); ++i) {
        const GlyphQuad& g = overlay.glyphs[i];
        CHECK(g.p0.x >= 0);
        CHECK(g.p1.x <= static_cast<float>(ended.width_px));
        CHECK(g.p0.y >= std::max(L.panel.y + L.panel.height, L.plot.y + L.plot.height));
    }
    // Slow motion: the time column's label says how much slower ("time (4x slower)").
    FrameOptions slow = o;
    slow.slow_motion = 4;
    CHECK(glyph_count(build_frame(s, slow, font)) > plain);
}

// The window draws the scene only where its list changed since the last frame (changed_regions.h):
// the regions must hold every pixel a changed primitive touched, before and after, and nothing
// changed must give no region; a change of frame (size, layers, clips) asks for the whole list.
TEST_CASE("the regions where a draw list changed hold every primitive that moved, before and after", "[render]") {
    DrawList a;
    a.width_px = 800;
    a.height_px = 600;
    a.bounds = ClipRect{100, 50, 700, 500};
    Layer& ramp = a.new_layer(ClipRect{100, 50, 700, 500});
    ramp.triangles.push_back({{120, 500}, {780, 520}, {120, 540}, rgb8(90, 90, 90)});
    for (int i = 0; i < 50; ++i)
        ramp.shapes.push_back(disc({200.0f + 2.0f * static_cast<float>(i), 150.0f}, 1.5f, rgb8(200, 50, 50)));
    a.new_layer(ClipRect{110, 300, 300, 240}).shapes.push_back(disc({250, 400}, 60.0f, rgb8(30, 60, 160)));

    const std::optional<std::vector<ClipRect>> same = changed_regions(a, a);
    REQUIRE(same);
    CHECK(same->empty());

    // One grain moves 10 px: one small region holding both of its places, inside the layer's clip.
    DrawList b = a;
    b.layers[0].shapes[7].a = b.layers[0].shapes[7].b = {224.0f, 160.0f};
    const std::optional<std::vector<ClipRect>> moved = changed_regions(a, b);
    REQUIRE(moved);
    REQUIRE(moved->size() == 1);
    const ClipRect r = moved->front();
    for (const Shape& s : {a.layers[0].shapes[7], b.layers[0].shapes[7]}) {
        const ClipRect px = pixels_touched(s);
        CHECK(intersection(r, px) == px);
    }
    CHECK(r.width * r.height < 30 * 30);
    CHECK(!overlap(r, pixels_touched(a.layers[1].shapes[0])));  // the close-up's disc is not redrawn

    // A change in the second layer adds a region inside its clip; a disc leaving the frame is cut.
    DrawList c = b;
    c.layers[1].shapes[0].a = c.layers[1].shapes[0].b = {250.0f, 420.0f};
    const std::optional<std::vector<ClipRect>> two = changed_regions(a, c);
    REQUIRE(two);
    CHECK(two->size() == 2);
    for (const ClipRect& x : *two) CHECK(intersection(x, *c.bounds) == x);

    // A grain added at the end of a layer is a change where it is drawn.
    DrawList d = a;
    d.layers[0].shapes.push_back(disc({600, 200}, 3.0f, rgb8(0, 0, 0)));
    const std::optional<std::vector<ClipRect>> added = changed_regions(a, d);
    REQUIRE(added);
    REQUIRE(added->size() == 1);
    CHECK(overlap(added->front(), pixels_touched(d.layers[0].shapes.back())));

    // Another frame: the whole list.
    DrawList e = a;
    e.width_px = 801;
    CHECK(!changed_regions(a, e));
    DrawList f = a;
    f.new_layer();
    CHECK(!changed_regions(a, f));
    DrawList g = a;
    g.layers[1].clip = ClipRect{110, 300, 310, 240};
    CHECK(!changed_regions(a, g));
}

TEST_CASE("regions close together merge, far apart stay apart, and many become one", "[render]") {
    std::vector<ClipRect> regions;
    add_region(regions, {10, 10, 20, 20});
    add_region(regions, {300, 300, 20, 20});
    CHECK(regions.size() == 2);
    add_region(regions, {12, 12, 20, 20});  // mostly the first: one rectangle around both
    REQUIRE(regions.size() == 2);
    CHECK(std::count(regions.begin(), regions.end(), ClipRect{10, 10, 22, 22}) == 1);
    // Two thin strips crossing at a corner stay apart: one rectangle around both would be the frame.
    std::vector<ClipRect> strips;
    add_region(strips, {0, 0, 800, 3});
    add_region(strips, {0, 0, 3, 600});
    CHECK(strips.size() == 2);
    add_region(strips, {});  // nothing to add
    CHECK(strips.size() == 2);
    std::vector<ClipRect> many;
    for (int i = 0; i < 10; ++i) add_region(many, {100 * i, 0, 5, 5});
    REQUIRE(many.size() <= 6);
    for (int i = 0; i < 10; ++i) {
        const ClipRect r{100 * i, 0, 5, 5};
        CHECK(std::any_of(many.begin(), many.end(), [&](const ClipRect& m) { return intersection(m, r) == r; }));
    }
}

// A region's edge never crosses a point sprite (llvmpipe scissors them block by block): the regions
// grow to hold each sprite disc they reach whole, and the discs that disc reaches in turn. Small discs
// are composited into an image cut to the region (disc_splat.h) and need no room.
TEST_CASE("regions grow to hold every disc they reach, whole", "[render]") {
    DrawList l;
    l.width_px = 400;
    l.height_px = 300;
    Layer& layer = l.new_layer();
    const float r = kSplatMaxRadiusPx + 1.0f;  // a sprite, not composited
    for (int i = 0; i < 5; ++i)
        layer.shapes.push_back(disc({100.0f + 2.0f * r * static_cast<float>(i), 100.0f}, r, rgb8(1, 2, 3)));
    layer.shapes.push_back(disc({300, 250}, r, rgb8(1, 2, 3)));  // far away: not taken in
    std::vector<ClipRect> regions{{99, 99, 3, 3}};
    hold_whole_discs(l, pixels_of(l), regions);
    REQUIRE(regions.size() == 1);
    for (int i = 0; i < 5; ++i) {
        const ClipRect px = pixels_touched(layer.shapes[static_cast<std::size_t>(i)]);
        CHECK(intersection(regions[0], px) == px);
    }
    CHECK(!overlap(regions[0], pixels_touched(layer.shapes[5])));

    // The same row of discs small enough to be composited: the region stays as it was.
    for (Shape& s : layer.shapes) s.radius = kSplatMaxRadiusPx;
    std::vector<ClipRect> small{{99, 99, 3, 3}};
    hold_whole_discs(l, pixels_of(l), small);
    CHECK(small == std::vector<ClipRect>{{99, 99, 3, 3}});
}

// The CPU's compositing of small discs (disc_splat.h), without GL: the sprites' coverage formula at
// the centre, at the edge and past the fringe; an outline's colour at the rim; and an image cut to a
// clip holds the uncut image's pixels there.
TEST_CASE("small discs composite to the sprites' coverage, the same pixels however the clip cuts them", "[render]") {
    const Shape opaque = disc({10.5f, 10.5f}, 3.0f, rgb8(255, 0, 0));
    const Shape ringed = disc({30.0f, 10.5f}, 4.0f, rgb8(0, 0, 255), Tag::grain, 1.0f, rgb8(0, 255, 0));
    CHECK(splat_eligible(opaque));
    CHECK(splat_eligible(ringed));
    CHECK_FALSE(splat_eligible(disc({0, 0}, kSplatMaxRadiusPx + 0.01f, rgb8(1, 2, 3))));
    CHECK_FALSE(splat_eligible(segment({0, 0}, {4, 0}, 2.0f, rgb8(1, 2, 3))));
    const std::vector<const Shape*> shapes{&opaque, &ringed};
    DiscSplat whole;
    SplatScratch scratch;
    splat_discs(shapes, 0, shapes.size(), {0, 0, 64, 32}, whole, scratch);
    // The pixels whose centres the discs' coverage reaches: from 7 (centre 7.5, 3 px from the first
    // disc's) to 33 (3.5 px from the second's), and from 6 to 14 down.
    CHECK(whole.box == ClipRect{7, 6, 27, 9});
    const auto at = [](const DiscSplat& s, int x, int y, int c) {
        return int{s.rgba[(static_cast<size_t>(y - s.box.y) * static_cast<size_t>(s.box.width) +
                           static_cast<size_t>(x - s.box.x)) * 4 + static_cast<size_t>(c)]};
    };
    CHECK(at(whole, 10, 10, 0) == 255);  // the centre: all red, opaque
    CHECK(at(whole, 10, 10, 3) == 255);
    // A pixel whose centre is 3 px from the disc's centre is half covered (0.5 - (3 - 3)).
    CHECK(at(whole, 13, 10, 3) == 128);
    CHECK(at(whole, 13, 10, 0) == 128);  // premultiplied
    CHECK(at(whole, 14, 10, 3) == 0);    // 4 px away: past the half-pixel fringe
    // The ringed disc: blue inside, green in its one-pixel outline (a pixel 3.5 px from the centre: the
    // outline's colour and whole coverage).
    CHECK(at(whole, 30, 10, 2) == 255);
    CHECK(at(whole, 33, 10, 1) == 255);
    CHECK(at(whole, 33, 10, 2) == 0);
    // Cut to a clip across both discs: the same bytes there.
    DiscSplat cut;
    splat_discs(shapes, 0, shapes.size(), {12, 8, 20, 4}, cut, scratch);
    REQUIRE(cut.box == ClipRect{12, 8, 20, 4});
    for (int y = 8; y < 12; ++y)
        for (int x = 12; x < 32; ++x)
            for (int c = 0; c < 4; ++c) {
                INFO(x << ", " << y << " channel " << c);
                CHECK(at(cut, x, y, c) == at(whole, x, y, c));
            }
    // A clip the discs do not reach, and a disc off in the far distance: nothing, no crash.
    splat_discs(shapes, 0, shapes.size(), {100, 100, 10, 10}, cut, scratch);
    CHECK(cut.box.empty());
    const Shape far = disc({3e9f, -3e9f}, 2.0f, rgb8(1, 2, 3));
    const std::vector<const Shape*> lost{&far};
    splat_discs(lost, 0, 1, {0, 0, 64, 32}, cut, scratch);
    CHECK(cut.box.empty());
}
