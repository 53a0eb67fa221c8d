// Headless rendering end to end (OSMesa, no display): the expected frames, each a valid PNG of the
// requested size; the background at the corners and the shell where it is; byte-identical frames
// from two renders; the run's files as `polyroll run` writes them; bad flags refused with exit 2.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include "render/disc_splat.h"
#include "render/font.h"
#include "render/frame_builder.h"
#include "render/frame_encoder.h"
#include "render/gl_renderer.h"
#include "render/offscreen_osmesa.h"
#include "render/png_writer.h"
#include "render/render_sequence.h"
#include "render/snapshot.h"
#include "sim/geometry/shell_pose.h"
#include "test_helpers.h"

using namespace polyroll;
using namespace polyroll::render;
namespace fs = std::filesystem;

namespace {

const polyroll::test::Scratch render_scratch("render-", true);

struct Rgb {
    int r, g, b;
};
Rgb pixel(const DecodedPng& im, int x, int y) {
    const size_t i = (static_cast<size_t>(y) * static_cast<size_t>(im.width) + static_cast<size_t>(x)) * 3;
    return {im.rgb[i], im.rgb[i + 1], im.rgb[i + 2]};
}
int distance(Rgb a, Rgba b) {
    return std::abs(a.r - static_cast<int>(std::lround(b.r * 255))) +
           std::abs(a.g - static_cast<int>(std::lround(b.g * 255))) +
           std::abs(a.b - static_cast<int>(std::lround(b.b * 255)));
}

// A short run of the default scene: 0.3 s simulated.
Scene short_scene() { return test::scene_with({{"run", {{"time_limit_s", 0.3}}}}); }

SequenceSettings small_settings(int w, int h) {
    SequenceSettings st;
    st.frame.width_px = w;
    st.frame.height_px = h;
    st.fps = 30.0;
    st.hold_s = 0.1;
    st.encoder_threads = 2;
    return st;
}

using Cli = polyroll::test::CommandResult;
Cli run_cli(const std::string& args, const std::string& env = "") {
    return polyroll::test::run_command(env + (env.empty() ? "" : " ") + std::string(POLYROLL_EXE) + " " + args);
}

}  // namespace

TEST_CASE("a headless render writes the expected PNG frames with the shell where it is", "[render]") {
    const fs::path dir = render_scratch("pixels");
    const Scene scene = short_scene();
    const SequenceSettings st = small_settings(640, 360);
    const SequenceResult res = render_sequence(scene, st, dir);

    // 0.3 s at 30 frames/s: frames at 0, 1/30, ..., 0.3 s, then 0.1 s of hold.
    REQUIRE(res.run.measured.end_time_s == Approx(0.3));
    const long expected = static_cast<long>(std::floor(0.3 * 30 + 1e-6)) + 1 + 3;
    CHECK(res.run_frames + res.hold_frames == expected);
    for (long i = 1; i <= expected; ++i) {
        const fs::path f = dir / frame_file_name(i);
        REQUIRE(fs::exists(f));
        const DecodedPng im = read_png(f);  // throws if not a valid PNG
        CHECK(im.width == 640);
        CHECK(im.height == 360);
    }
    CHECK(!fs::exists(dir / frame_file_name(expected + 1)));
    // No temporary files left behind.
    for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().filename().string().front() != '.');

    // The last frame shows the final state: rebuild its draw list to know where things are.
    const DecodedPng last = read_png(dir / frame_file_name(expected));
    for (auto [x, y] : {std::pair{0, 0}, {639, 0}, {0, 359}, {639, 359}}) {
        INFO("corner " << x << "," << y);
        CHECK(distance(pixel(last, x, y), palette::background) == 0);
    }
    Simulation sim(scene);
    while (sim.step()) {
    }
    const Snapshot snap = sim.snapshot();
    const FrameOptions options = options_for_run(st.frame, res.run);
    const FontAtlas font(find_font_dir(), frame_fonts(options));
    const DrawList dl = build_frame(snap, options, font);
    // The close-up's outer edges (its widest outline strokes) are drawn in the outline colour.
    int edges = 0, hits = 0;
    for (const Layer& layer : dl.layers) {
        if (!layer.clip) continue;
        float widest = 0;
        for (const Shape& s : layer.shapes)
            if (s.tag == Tag::shell_outline) widest = std::max(widest, s.radius);
        for (const Shape& s : layer.shapes) {
            if (s.tag != Tag::shell_outline || s.radius < widest) continue;
            ++edges;
            const int cx = static_cast<int>((s.a.x + s.b.x) / 2), cy = static_cast<int>((s.a.y + s.b.y) / 2);
            int best = 1 << 20;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) best = std::min(best, distance(pixel(last, cx + dx, cy + dy),
                                                                                 palette::shell_outline));
            hits += best < 60;
        }
    }
    CHECK(edges == snap.sides);
    CHECK(hits == edges);
    // The lid dot at the close-up's centre is black; the light inside of the shell is around it.
    const FrameLayout L = frame_layout(options);
    REQUIRE(L.inset);
    const int ix = static_cast<int>(L.inset->x + L.inset->width / 2), iy = static_cast<int>(L.inset->y + L.inset->height / 2);
    CHECK(distance(pixel(last, ix, iy), palette::lid_dot) < 40);
    // In the main view the shell sits near the top of the ramp, not in the empty middle of the frame
    // (seen on the last moving frame: the held ones carry the outcome banner there).
    const DecodedPng moving = read_png(dir / frame_file_name(res.run_frames));
    CHECK(distance(pixel(moving, 320, 120), palette::background) == 0);
}

namespace {

// An empty list of the frame's size on the default background, for the renderer's own tests.
DrawList blank_list(int width_px, int height_px) {
    DrawList list;
    list.width_px = width_px;
    list.height_px = height_px;
    list.background = palette::background;
    return list;
}

// The list drawn whole and read back, RGBA rows from the bottom.
std::vector<std::uint8_t> drawn_rgba(GlRenderer& gl, OffscreenContext& context, const DrawList& list) {
    gl.draw(list);
    std::vector<std::uint8_t> rgba(static_cast<size_t>(list.width_px) * static_cast<size_t>(list.height_px) * 4);
    context.read_rgba_bottom_up(rgba.data());
    return rgba;
}

}  // namespace

TEST_CASE("discs of one colour draw the same pixels as discs coloured one by one", "[render]") {
    // The renderer draws a long run of discs sharing a fill and an outline with the colours as uniforms
    // (gl_renderer.cpp, kOneColourRunMin), shorter runs with a colour per point. An invisible disc in
    // the middle (alpha 0: blending leaves every pixel as it is) cuts the run in two halves too short
    // for the uniforms, so the second list is drawn the other way; the pixels must not change. The
    // discs are larger than kSplatMaxRadiusPx, so they are sprites (smaller ones are composited on the
    // CPU: the test below).
    constexpr int kW = 120, kH = 80;
    OffscreenContext context(kW, kH);
    GlRenderer gl;
    DrawList one = blank_list(kW, kH);
    Layer& layer = one.new_layer();
    const Rgba fill = rgb8(200, 160, 60), outline = rgb8(90, 60, 20);
    for (int i = 0; i < 40; ++i) {
        const int row = i / 10, column = i % 10;
        const Px centre{6.0f + 11.3f * static_cast<float>(column), 8.0f + 17.7f * static_cast<float>(row)};
        layer.shapes.push_back(disc(centre, kSplatMaxRadiusPx + 0.2f + 0.4f * static_cast<float>(i % 3), fill,
                                    Tag::grain, 0.7f, outline));
    }
    DrawList split = one;
    split.layers[0].shapes.insert(split.layers[0].shapes.begin() + 20,
                                  disc({50.0f, 30.0f}, kSplatMaxRadiusPx + 1.0f, Rgba{1.0f, 0.0f, 0.0f, 0.0f},
                                       Tag::grain, 0.7f, Rgba{0.0f, 0.0f, 1.0f, 0.0f}));
    const std::vector<std::uint8_t> a = drawn_rgba(gl, context, one), b = drawn_rgba(gl, context, split);
    // The discs are there: most of their pixels are not the background.
    int covered = 0;
    for (size_t i = 0; i < a.size(); i += 4)
        if (a[i] != static_cast<std::uint8_t>(std::lround(palette::background.r * 255.0f))) ++covered;
    CHECK(covered > 1500);
    CHECK(a == b);
}

// Small discs are composited on the CPU into one image drawn as one quad (render/disc_splat.h) where
// a point sprite each cost a software GL 0.8 us. The picture must be the sprites' picture: the same
// coverage and outline formula, blended in the same order, rounded to 8 bits once instead of once a
// disc. A crowded pile of translucent and opaque discs, outlined or not, across the frame's edge:
// every channel within 3 levels of 255 (a pixel under n discs may differ by up to n/2 levels through
// the sprites' rounding alone), less than half a level on average.
TEST_CASE("small discs composited on the CPU draw the point sprites' picture", "[render]") {
    constexpr int kW = 96, kH = 64;
    OffscreenContext context(kW, kH);
    GlRenderer gl;
    DrawList list = blank_list(kW, kH);
    Layer& layer = list.new_layer();
    for (int i = 0; i < 600; ++i) {
        // Halfway, a shape that is not a disc (a quad): the discs before and after it are two images.
        if (i == 300) layer.shapes.push_back(segment({2.0f, 60.0f}, {94.0f, 4.0f}, 5.0f, rgb8(40, 40, 40, 0.8f)));
        // A deterministic scatter, denser in the middle, some discs half outside the frame.
        const float u = static_cast<float>((i * 37) % 101) / 100.0f, v = static_cast<float>((i * 53) % 97) / 96.0f;
        const Px centre{-3.0f + 102.0f * u * u * (3.0f - 2.0f * u), -2.0f + 68.0f * v};
        const float radius = 0.25f + 3.7f * static_cast<float>((i * 29) % 31) / 30.0f;
        const Rgba fill = i % 3 == 0 ? rgb8(200, 160, 60, 0.6f) : rgb8(60 + i % 150, 90, 200 - i % 120);
        layer.shapes.push_back(i % 2 ? disc(centre, radius, fill, Tag::grain, 0.6f, rgb8(90, 60, 20))
                                     : disc(centre, radius, fill, Tag::grain));
    }
    const auto drawn = [&](bool composite) {
        gl.composite_small_discs(composite);
        return drawn_rgba(gl, context, list);
    };
    const std::vector<std::uint8_t> sprites = drawn(false), composited = drawn(true);
    REQUIRE(sprites.size() == composited.size());
    int worst = 0, covered = 0;
    long sum = 0;
    for (size_t i = 0; i < sprites.size(); i += 4) {
        if (sprites[i] != static_cast<std::uint8_t>(std::lround(palette::background.r * 255.0f))) ++covered;
        int d = 0;
        for (size_t c = 0; c < 3; ++c) d = std::max(d, std::abs(int{sprites[i + c]} - int{composited[i + c]}));
        worst = std::max(worst, d);
        sum += d;
    }
    const double mean = static_cast<double>(sum) / covered;
    INFO("worst " << worst << ", mean " << mean << " levels over " << covered << " covered pixels");
    CHECK(covered > kW * kH / 2);
    CHECK(worst <= 3);
    CHECK(mean < 0.5);
    // And composited again, byte for byte the same (nothing left over from the last image).
    CHECK(drawn(true) == composited);
}

TEST_CASE("two renders of the same scene give byte-identical frames", "[render]") {
    const fs::path a = render_scratch("det-a"), b = render_scratch("det-b");
    const Scene scene = test::scene_with({{"run", {{"time_limit_s", 0.2}}}});
    SequenceSettings st = small_settings(320, 180);
    st.frame.grain_colouring = GrainColouring::speed;
    const SequenceResult ra = render_sequence(scene, st, a);
    st.encoder_threads = 1;  // a different pool size must not change a byte
    const SequenceResult rb = render_sequence(scene, st, b);
    const long n = ra.run_frames + ra.hold_frames;
    REQUIRE(n == rb.run_frames + rb.hold_frames);
    REQUIRE(n > 5);
    for (long i = 1; i <= n; ++i) {
        INFO(frame_file_name(i));
        CHECK(polyroll::test::read_file(a / frame_file_name(i)) == polyroll::test::read_file(b / frame_file_name(i)));
    }
    // And the frames do change as the polygon moves.
    CHECK(polyroll::test::read_file(a / frame_file_name(1)) != polyroll::test::read_file(a / frame_file_name(n)));
}

TEST_CASE("polyroll render writes the run's files as polyroll run does", "[render][cli]") {
    const fs::path base = render_scratch("cli");
    const std::string scene = "--time-limit 0.2 --sides 8 --fill 0.375 --material peas --angle 12";
    const Cli run = run_cli("run " + scene + " --out " + (base / "run").string());
    REQUIRE(run.exit_code == 0);
    const Cli render = run_cli("render " + scene + " --size 320x180 --fps 20 --hold 0.5 --out " + (base / "frames").string());
    INFO(render.out);
    REQUIRE(render.exit_code == 0);
    CHECK(render.out.find("frame 15/15") != std::string::npos);  // progress: 0.2 s x 20 + 1, and 10 held
    CHECK(fs::exists(base / "frames" / frame_file_name(15)));
    CHECK(!fs::exists(base / "frames" / frame_file_name(16)));
    for (const char* f : {"trajectory.csv", "impacts.csv"}) CHECK(polyroll::test::read_file(base / "run" / f) == polyroll::test::read_file(base / "frames" / f));
    auto summary = [](const fs::path& p) {
        nlohmann::json j = nlohmann::json::parse(polyroll::test::read_file(p));
        j["results"].erase("wall_time_s");  // the only field that depends on the clock
        return j;
    };
    CHECK(summary(base / "run" / "summary.json") == summary(base / "frames" / "summary.json"));
}

TEST_CASE("polyroll render refuses bad flags with one line, exit 2 and nothing written", "[render][cli][bad-input]") {
    const fs::path base = render_scratch("bad");
    const fs::path out = base / "new";
    struct Case {
        std::string args;
        std::vector<std::string> words;
    };
    const std::vector<Case> cases = {
        {"--size 0x0", {"--size 0x0", "320"}},
        {"--size 100x100", {"--size 100x100", "320", "180"}},  // unreadable: refused
        {"--size 1280", {"--size 1280", "WIDTHxHEIGHT"}},
        {"--size 99999x720", {"--size 99999x720", "7680"}},
        {"--fps 0", {"--fps 0", "1 to 240"}},
        {"--fps 1000", {"--fps 1000", "1 to 240"}},
        {"--slow 0", {"--slow 0", "1 to 100"}},
        {"--color-by mood", {"--color-by mood", "material, speed"}},
        {"--colour-by mood", {"--colour-by mood", "material, speed"}},  // echoed as typed
        {"--video /nonexistent-folder/x.mp4", {"/nonexistent-folder", "does not exist"}},
        // Checked before any frame is drawn, not found by ffmpeg after them all.
        {"--video x.txt", {"--video x.txt", "not a video format .txt", ".mp4, .mkv or .mov"}},
        {"--video x", {"--video x", "no extension", ".mp4, .mkv or .mov"}},
        {"--fill 2", {"fill.ratio = 2", "0 to 1"}},
    };
    for (const Case& c : cases)
        polyroll::test::expect_refused(polyroll::test::kPolyrollExe + " render --time-limit 0.1 " + c.args + " --out " + out.string(),
                                       c.words, out);
    // An unwritable folder, and a non-empty one without --force.
    const fs::path file = base / "a-file";
    std::ofstream(file) << "x";
    Cli r = run_cli("render --time-limit 0.1 --out " + (file / "frames").string());
    CHECK(r.exit_code == 2);
    CHECK(r.out.find((file / "frames").string()) != std::string::npos);
    const fs::path full = base / "full";
    fs::create_directories(full);
    std::ofstream(full / "keep.txt") << "x";
    r = run_cli("render --time-limit 0.1 --out " + full.string());
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("--force") != std::string::npos);
    CHECK(!fs::exists(full / frame_file_name(1)));
    CHECK(fs::exists(full / "keep.txt"));
}

TEST_CASE("render with --video makes a video of every frame with ffmpeg", "[render][cli][video]") {
    // ffmpeg (and its ffprobe) come from Debian's ffmpeg package, in third_party/debian-packages.txt.
    INFO("ffmpeg and ffprobe are needed (Debian package ffmpeg, in third_party/debian-packages.txt)");
    REQUIRE(polyroll::test::run_command("command -v ffmpeg && command -v ffprobe").exit_code == 0);
    const fs::path base = render_scratch("video-made");
    // Odd sides: the video pads them to even ones (yuv420p needs even sides).
    const Cli r = run_cli("render --time-limit 0.5 --fps 10 --size 321x181 --hold 0 --out " + (base / "f").string() +
                          " --video " + (base / "v.mp4").string());
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    REQUIRE(fs::exists(base / "v.mp4"));
    int frames = 0;
    for (const auto& e : fs::directory_iterator(base / "f")) frames += e.path().extension() == ".png";
    REQUIRE(frames > 1);
    const auto probe = polyroll::test::run_command(
        "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames,width,height "
        "-of csv=p=0 " + (base / "v.mp4").string());
    INFO(probe.out);
    REQUIRE(probe.exit_code == 0);
    CHECK(probe.out == "322,182," + std::to_string(frames) + "\n");
    // Nothing but the video and the frames' folder: ffmpeg's temporary was renamed into place.
    const auto entries = std::distance(fs::directory_iterator(base), fs::directory_iterator());
    CHECK(entries == 2);
    fs::remove_all(base);
}

TEST_CASE("render with --video but no ffmpeg says how to get it and still writes the frames", "[render][cli]") {
    const fs::path base = render_scratch("video");
    // An empty PATH hides any installed ffmpeg.
    const Cli r = run_cli("render --time-limit 0.1 --size 320x180 --hold 0 --out " + (base / "f").string() +
                               " --video " + (base / "v.mp4").string(),
                           "env PATH=/nonexistent");
    INFO(r.out);
    CHECK(r.exit_code == 1);
    CHECK(r.out.find("ffmpeg is not installed") != std::string::npos);
    CHECK(r.out.find("apt-get install ffmpeg") != std::string::npos);
    CHECK(fs::exists(base / "f" / frame_file_name(1)));
    CHECK(fs::exists(base / "f" / "summary.json"));
    CHECK(!fs::exists(base / "v.mp4"));
}

TEST_CASE("render --video may go into the --out folder the render creates", "[render][cli]") {
    // frames/x.mp4 with --out frames was refused because frames/ did not exist yet. Without
    // ffmpeg on PATH the render runs and says so (exit 1), which shows the video's folder was accepted.
    const fs::path base = render_scratch("video-in-out");
    const Cli r = run_cli("render --time-limit 0.1 --size 320x180 --hold 0 --out " + (base / "f").string() +
                              " --video " + (base / "f" / "v.mp4").string(),
                          "env PATH=/nonexistent");
    INFO(r.out);
    CHECK(r.exit_code == 1);
    CHECK(r.out.find("does not exist") == std::string::npos);
    CHECK(r.out.find("ffmpeg is not installed") != std::string::npos);
    CHECK(fs::exists(base / "f" / frame_file_name(1)));
    // A relative name goes into the --out folder, wherever the command runs.
    fs::create_directories(base / "elsewhere");
    const Cli relative = run_cli("render --time-limit 0.1 --size 320x180 --hold 0 --out " + (base / "r").string() +
                                     " --video v.mp4",
                                 "cd " + (base / "elsewhere").string() + " && env PATH=/nonexistent");
    INFO(relative.out);
    CHECK(relative.exit_code == 1);
    CHECK(relative.out.find("--video " + (base / "r" / "v.mp4").string() + ": ffmpeg is not installed") !=
          std::string::npos);
    CHECK(fs::is_empty(base / "elsewhere"));
    // A folder that is neither --out nor existing is still refused, before anything is written.
    const Cli other = run_cli("render --time-limit 0.1 --out " + (base / "g").string() + " --video " +
                              (base / "h" / "v.mp4").string());
    CHECK(other.exit_code == 2);
    CHECK(other.out.find("does not exist (allowed: an existing folder or the --out folder)") != std::string::npos);
    CHECK(!fs::exists(base / "g"));
    fs::remove_all(base);
}

TEST_CASE("polyroll render plays every model: the reduced models' frames turn the polygon as they compute", "[render][cli][models]") {
    const fs::path base = render_scratch("models");
    for (const char* model : {"segments", "rigid"}) {
        INFO(model);
        const std::string scene = std::string("--time-limit 1 --model ") + model;
        const fs::path run_dir = base / (std::string(model) + "-run"), frames = base / model;
        REQUIRE(run_cli("run " + scene + " --out " + run_dir.string()).exit_code == 0);
        const Cli render = run_cli("render " + scene + " --size 320x180 --fps 10 --hold 0 --out " + frames.string());
        INFO(render.out);
        REQUIRE(render.exit_code == 0);
        // 1 s at 10 frames/s: frames at 0, 0.1, ..., 1 s.
        CHECK(fs::exists(frames / frame_file_name(11)));
        CHECK(!fs::exists(frames / frame_file_name(12)));
        for (const char* f : {"trajectory.csv", "impacts.csv"})
            CHECK(polyroll::test::read_file(run_dir / f) == polyroll::test::read_file(frames / f));
        // The polygon moves between the first frame and the last.
        CHECK(polyroll::test::read_file(frames / frame_file_name(1)) != polyroll::test::read_file(frames / frame_file_name(11)));
    }
    // The frame shows the shell where the model puts it: the snapshot's pose is the rolling pose.
    Scene s = test::scene_with({{"run", {{"model", "segments"}, {"time_limit_s", 1.0}}}});
    std::unique_ptr<ModelRun> run = start_run(s);
    while (run->step()) {
    }
    const Snapshot snap = run->snapshot();
    const ShellPose pose = rolling_pose(s, snap.now.position_m, snap.now.angle_deg);
    CHECK(snap.shell_centre_m.x == Approx(pose.centre_m.x));
    CHECK(snap.shell_angle_rad == Approx(pose.angle_rad));
    CHECK(snap.now.position_m == Approx(run->measured().distance_m));
}
