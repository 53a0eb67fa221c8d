// polyroll render: a scene rendered headless (OSMesa, no display or GPU) to a PNG frame sequence,
// with the run's summary.json, trajectory.csv and impacts.csv beside the frames, and optionally a
// video made with ffmpeg when it is installed.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <string_view>
#include <unistd.h>

#include <fmt/core.h>

#include "cli/commands.h"
#include "cli/interrupt_cleanup.h"
#include "cli/scene_options.h"
#include "process/child_process.h"
#include "render/frame_encoder.h"
#include "render/render_sequence.h"
#include "sim/files/atomic_file.h"
#include "sim/errors.h"
#include "sim/files/results_io.h"
#include "sim/scene/scene_json.h"

namespace polyroll::cli {

namespace {

namespace fs = std::filesystem;

// The limits of the render flags, in one place.
constexpr double kMaxFps = 240.0;
constexpr int kMaxSlow = 100;
constexpr int kMinWidth = 320, kMinHeight = 180, kMaxWidth = 7680, kMaxHeight = 4320;
constexpr double kMaxHold = 60.0;
// The containers ffmpeg writes H.264 into, as --video's extension (lower case).
constexpr std::array<std::string_view, 3> kVideoExtensions = {".mp4", ".mkv", ".mov"};

std::string video_extensions_text() {
    return fmt::format("{}, {} or {}", kVideoExtensions[0], kVideoExtensions[1], kVideoExtensions[2]);
}

struct RenderOptions {
    SceneOptions scene;
    std::string out;
    std::string size = "1280x720";
    double fps = 30.0;
    int slow = 1;
    double hold_s = 1.0;
    bool follow = false;
    std::string colour_by = "material";
    std::string colour_flag = "--color-by";  // as typed, for messages: --color-by or --colour-by
    std::string video;
    bool force = false;
};

struct Size {
    int width = 0, height = 0;
};

Size parse_size(const std::string& text) {
    static const std::regex pattern(R"(\s*(\d{1,6})\s*[xX]\s*(\d{1,6})\s*)");
    std::smatch m;
    const std::string allowed = fmt::format("allowed: WIDTHxHEIGHT, width {}..{}, height {}..{}, e.g. 1280x720",
                                            kMinWidth, kMaxWidth, kMinHeight, kMaxHeight);
    if (!std::regex_match(text, m, pattern)) throw InputError(fmt::format("--size {}: not a size ({})", text, allowed));
    const Size s{std::stoi(m[1]), std::stoi(m[2])};
    if (s.width < kMinWidth || s.width > kMaxWidth || s.height < kMinHeight || s.height > kMaxHeight)
        throw InputError(fmt::format("--size {}: out of range ({})", text, allowed));
    return s;
}

// ffmpeg writes the video under a temporary name beside it (same extension: it names the format) that
// is renamed into place once whole, so a killed render never leaves half a video under its name.
fs::path video_temp_path(const std::string& video) {
    const fs::path v(video);
    return v.parent_path() / fmt::format(".{}.tmp-{}{}", v.stem().string(), ::getpid(), v.extension().string());
}

std::vector<std::string> ffmpeg_args(const std::string& ffmpeg, const RenderOptions& o, const std::string& output) {
    return {ffmpeg, "-y", "-hide_banner", "-loglevel", "error", "-framerate", fmt::format("{:g}", o.fps), "-i",
            (fs::path(o.out) / "frame_%06d.png").string(),
            // yuv420p plays everywhere but needs even sides.
            "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", output};
}

std::string shell_quote(const std::string& s) {
    if (s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./=%:") ==
        std::string::npos)
        return s;
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string command_line(const std::vector<std::string>& args) {
    std::string line;
    for (const std::string& a : args) line += (line.empty() ? "" : " ") + shell_quote(a);
    return line;
}

// Runs ffmpeg and waits; returns its exit status (or -1 if it could not start or was killed).
int run_ffmpeg(const std::vector<std::string>& args) {
    const process::ChildExit e = process::run_child(args);
    return e.started && e.signal == 0 ? e.exit_code : -1;
}

std::string no_ffmpeg_message(const RenderOptions& o) {
    return fmt::format(
        "--video {}: ffmpeg is not installed, so no video was made (the frames are in {}).\n"
        "  Install it with:  sudo apt-get install ffmpeg\n"
        "  then make the video from these frames with:\n"
        "  {}",
        o.video, o.out, command_line(ffmpeg_args("ffmpeg", o, o.video)));
}

// A progress line: in place on a terminal, otherwise a line every tenth of the way.
class ProgressLine {
public:
    ProgressLine(int width_px, int height_px, std::string folder)
        : tty_(::isatty(STDERR_FILENO) != 0), width_px_(width_px), height_px_(height_px), folder_(std::move(folder)) {}
    void update(const render::SequenceProgress& p) {
        // Once the data run has said how many frames there are: the count, the size and where they go,
        // before the countdown.
        if (!announced_) {
            announced_ = true;
            fmt::print(stderr, "  {} frames of {}x{} into {} (about {:.0f} MB of PNG at this size)\n",
                       p.frames_expected, width_px_, height_px_, folder_,
                       static_cast<double>(p.frames_expected) * kPngBytesPerPixel * width_px_ * height_px_ / 1e6);
        }
        const double fps = p.wall_s > 0 ? static_cast<double>(p.frames_done) / p.wall_s : 0.0;
        const double left = fps > 0 ? static_cast<double>(p.frames_expected - p.frames_done) / fps : 0.0;
        const std::string line = fmt::format("  rendering: frame {}/{}, {:.0f} frames/s, {:.1f} s left", p.frames_done,
                                             p.frames_expected, fps, left);
        if (tty_) {
            fmt::print(stderr, "\r{:<70}", line);
            if (p.frames_done >= p.frames_expected) fmt::print(stderr, "\n");
        } else {
            const long tenth = p.frames_done * 10 / std::max(1L, p.frames_expected);
            if (tenth > last_tenth_) {
                last_tenth_ = tenth;
                fmt::print(stderr, "{}\n", line);
            }
        }
        std::fflush(stderr);
    }

private:
    // Measured on the default scene at 1280x720: 57 MB for 544 frames, about 0.11 bytes a pixel.
    static constexpr double kPngBytesPerPixel = 0.11;
    bool tty_;
    int width_px_, height_px_;
    std::string folder_;
    bool announced_ = false;
    long last_tenth_ = 0;
};

void remove_old_frames(const fs::path& dir) {
    // With --force, frames of an earlier, longer render would otherwise trail the new sequence.
    static const std::regex frame(R"(frame_\d{6}\.png)");
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (std::regex_match(e.path().filename().string(), frame)) fs::remove(e.path(), ec);
}

// Every flag but --size checked before any work, so bad input leaves nothing behind; a relative
// --video made a file in the --out folder.
void check_flags(RenderOptions& o) {
    if (!(o.fps >= 1.0 && o.fps <= kMaxFps))
        throw InputError(fmt::format("--fps {:g}: out of range (allowed: 1 to {:g} frames per second)", o.fps, kMaxFps));
    if (o.slow < 1 || o.slow > kMaxSlow)
        throw InputError(fmt::format("--slow {}: out of range (allowed: 1 to {}, the slow-motion factor)", o.slow, kMaxSlow));
    if (!(o.hold_s >= 0.0 && o.hold_s <= kMaxHold))
        throw InputError(fmt::format("--hold {:g}: out of range (allowed: 0 to {:g} s)", o.hold_s, kMaxHold));
    if (o.colour_by != "material" && o.colour_by != "speed")
        throw InputError(fmt::format("{} {}: unknown (allowed: material, speed)", o.colour_flag, o.colour_by));
    if (!o.video.empty()) {
        // Checked before any frame is drawn: a video ffmpeg cannot write was found only after rendering
        // every frame. The extension names the container; these three hold H.264 (yuv420p).
        std::string ext = fs::path(o.video).extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (std::find(kVideoExtensions.begin(), kVideoExtensions.end(), ext) == kVideoExtensions.end()) {
            const std::string what = ext.empty() ? "no extension to name the format" : "not a video format " + ext;
            throw InputError(fmt::format("--video {}: {} (allowed: a file ending in {})", o.video, what,
                                         video_extensions_text()));
        }
        // A relative --video names a file in the --out folder, beside the frames it is made of (not in
        // the folder the command ran in); an absolute one goes where it says.
        if (fs::path(o.video).is_relative()) o.video = (fs::path(o.out) / o.video).string();
        // The video may go into the --out folder this render is about to create, or any existing folder.
        std::error_code ec;
        const fs::path parent = fs::weakly_canonical(fs::absolute(o.video), ec).parent_path();
        fs::path out_dir = fs::weakly_canonical(fs::absolute(o.out), ec);
        if (!out_dir.has_filename()) out_dir = out_dir.parent_path();  // --out frames/
        if (!fs::is_directory(parent, ec) && parent != out_dir)
            throw InputError(fmt::format("--video {}: the folder {} does not exist (allowed: an existing folder or "
                                         "the --out folder)",
                                         o.video, parent.string()));
    }
}

// The line that says what is about to be rendered.
void announce(const Scene& scene, const RenderOptions& o, const Size& size) {
    // An empty shell has no material to name ("r = 0 bb" read as if it held BBs).
    const std::string fill = scene.fill.ratio > 0.0
                                 ? fmt::format("r = {:g} {}", scene.fill.ratio, scene.fill.material.preset)
                                 : std::string("empty");
    fmt::print("polyroll render: n = {}, {}, theta = {:g} deg on {}, {}x{} at {:g} fps{}{}\n",
               scene.shell.sides, fill, scene.ramp.angle_deg,
               scene.ramp.preset.empty() ? "a custom ramp" : "the " + scene.ramp.preset + " ramp", size.width,
               size.height, o.fps,
               o.slow > 1 ? fmt::format(", {}x slow motion", o.slow) : "", o.follow ? ", following the polygon" : "");
    std::fflush(stdout);
}

// The race's lines: the preset, then each lane in its number.
void announce_race(const std::vector<Scene>& lanes, const RenderOptions& o, const Size& size) {
    fmt::print("polyroll render: preset {}, {} lanes side by side, {}x{} at {:g} fps{}{}\n", o.scene.preset(),
               lanes.size(), size.width, size.height, o.fps, o.slow > 1 ? fmt::format(", {}x slow motion", o.slow) : "",
               o.follow ? ", following the leading polygon" : "");
    for (size_t i = 0; i < lanes.size(); ++i) {
        const Scene& s = lanes[i];
        const std::string fill = s.fill.ratio > 0.0 ? fmt::format("r = {:g} {}", s.fill.ratio, s.fill.material.preset)
                                                    : std::string("empty");
        fmt::print("  lane {}     n = {}, {}, theta = {:g} deg on {}\n", i + 1, s.shell.sides, fill, s.ramp.angle_deg,
                   s.ramp.preset.empty() ? "a custom ramp" : "the " + s.ramp.preset + " ramp");
    }
    std::fflush(stdout);
}

// A race's lane's files go in a folder of their own: OUT/lane-1/summary.json, ...
fs::path lane_folder(const RenderOptions& o, size_t i) { return fs::path(o.out) / fmt::format("lane-{}", i + 1); }

// What was rendered, where, and how long it took.
void report(const render::SequenceResult& res, const RenderOptions& o) {
    const long total = res.run_frames + res.hold_frames;
    const double fps_wall = res.render_wall_s > 0 ? static_cast<double>(total) / res.render_wall_s : 0.0;
    const std::string folder = (fs::path(o.out) / "").string();
    fmt::print("  frames     {} ({} of the run, {} holding the end): {}{} ... {}\n", total, res.run_frames,
               res.hold_frames, folder, render::frame_file_name(1), render::frame_file_name(total));
    const bool race = res.lane_runs.size() > 1;
    double data_wall_s = 0.0;
    for (size_t i = 0; i < res.lane_runs.size(); ++i) {
        const Measurements& lm = res.lane_runs[i].measured;
        data_wall_s += res.lane_runs[i].wall_time_s;
        fmt::print("  {:<10} {} after {:.3f} s, distance {:.3f} m, {} face impact{}\n",
                   race ? fmt::format("lane {}", i + 1) : std::string("run"), to_string(lm.behaviour), lm.end_time_s,
                   lm.distance_m, lm.impacts.size(), lm.impacts.size() == 1 ? "" : "s");
    }
    fmt::print("  time       {:.2f} s rendering ({:.0f} frames/s) after {} {:.2f} s data run{}; {:.1f} MB of PNG\n",
               res.render_wall_s, fps_wall, race ? "the lanes'" : "a", data_wall_s, race ? "s" : "",
               static_cast<double>(res.png_bytes) / 1e6);
    // Joined as paths: --out frames/ must not print frames//summary.json.
    if (race)
        fmt::print("  files      {}, trajectory.csv, impacts.csv (and lane-2/ ... lane-{}/ alike)\n",
                   (lane_folder(o, 0) / "summary.json").string(), res.lane_runs.size());
    else
        fmt::print("  files      {}, trajectory.csv, impacts.csv\n", (fs::path(o.out) / "summary.json").string());
    std::fflush(stdout);

}

// The video from the frames, written whole or not at all; returns the exit code (`code` if it was made).
int make_video(const RenderOptions& o, const std::string& ffmpeg, int code) {
    if (ffmpeg.empty()) {
        fmt::print(stderr, "polyroll: {}\n", no_ffmpeg_message(o));
        return code == kExitOk ? kExitFailure : code;
    }
    const fs::path temp = video_temp_path(o.video);
    int status = run_ffmpeg(ffmpeg_args(ffmpeg, o, temp.string()));
    std::error_code ec;
    if (status == 0) {
        fs::rename(temp, o.video, ec);
        if (ec) status = -1;
    }
    if (status != 0) {
        fs::remove(temp, ec);
        fmt::print(stderr, "polyroll: --video {}: ffmpeg failed (exit status {}); the frames are in {}. The command "
                           "was:\n  {}\n",
                   o.video, status, o.out, command_line(ffmpeg_args(ffmpeg, o, o.video)));
        return code == kExitOk ? kExitFailure : code;
    }
    fmt::print("  video      {}\n", o.video);
    return code;
}

int render(const RenderOptions& given) {
    RenderOptions o = given;
    const Size size = parse_size(o.size);
    check_flags(o);
    const std::string ffmpeg = o.video.empty() ? std::string() : process::find_on_path("ffmpeg");
    const std::vector<Scene> lanes = o.scene.resolve_lanes();
    const Scene& scene = lanes.front();
    const std::optional<fs::path> created = prepare_output_dir(o.out, o.force);
    const CleanUpOnInterrupt on_interrupt("polyroll render", created);
    if (!o.video.empty() && ffmpeg.empty())
        fmt::print(stderr, "polyroll: note: ffmpeg is not installed: the frames will be written, but no video (how "
                           "to make one follows at the end)\n");

    render::SequenceSettings st;
    st.frame.width_px = size.width;
    st.frame.height_px = size.height;
    st.frame.follow = o.follow;
    st.frame.grain_colouring = o.colour_by == "speed" ? render::GrainColouring::speed : render::GrainColouring::material;
    st.fps = o.fps;
    st.slow = o.slow;
    st.hold_s = o.hold_s;

    const bool race = lanes.size() > 1;
    if (race) announce_race(lanes, o, size);
    else announce(scene, o, size);
    render::SequenceResult res;
    ProgressLine progress(size.width, size.height, o.out);
    try {
        if (o.force) remove_old_frames(o.out);
        const auto on_progress = [&](const render::SequenceProgress& p) { progress.update(p); };
        if (race) {
            res = render::render_race(lanes, st, o.out, on_progress);
            for (size_t i = 0; i < res.lane_runs.size(); ++i) {
                fs::create_directories(lane_folder(o, i));
                write_run_files(lane_folder(o, i).string(), res.lane_runs[i]);
            }
        } else {
            res = render::render_sequence(scene, st, o.out, on_progress);
            write_run_files(o.out, res.run);
        }
    } catch (...) {
        // Nothing half-written: a folder this render created goes with it.
        std::error_code ec;
        if (created) fs::remove_all(*created, ec);
        throw;
    }

    report(res, o);
    int code = kExitOk;
    for (size_t i = 0; i < res.lane_runs.size(); ++i) {
        const Measurements& m = res.lane_runs[i].measured;
        if (m.behaviour != Behaviour::diverged) continue;
        code = kExitDiverged;
        fmt::print(stderr, "polyroll: {}the run diverged {}\n", race ? fmt::format("lane {}: ", i + 1) : "",
                   m.divergence);
    }
    return o.video.empty() ? code : make_video(o, ffmpeg, code);
}

}  // namespace

Action add_render_command(Command& app) {
    auto opts = std::make_shared<RenderOptions>();
    Command sub = app.add_subcommand("render", "render a scene headless to PNG frames (and a video with ffmpeg)");
    sub.footer(
        "Frames are taken whenever simulated time has advanced by 1/(fps x slow), until the run ends, then\n"
        "the final state is held for --hold seconds. summary.json, trajectory.csv and impacts.csv go beside\n"
        "the frames, as 'polyroll run' writes them. No display or GPU is needed (OSMesa).\n"
        "Examples:\n"
        "  polyroll render --out frames/\n"
        "  polyroll render --sides 8 --fill 0.375 --material peas --angle 12 --fps 60 --size 1920x1080 \\\n"
        "      --out frames/oct --video oct.mp4\n"
        "  polyroll render --scene my-scene.json --follow --slow 4 --out frames/slow\n"
        "  polyroll render --preset race --out frames/race       # the window's race: its lanes side by side\n"
        "  polyroll render --preset race --lane 2 --out frames/lane2\n"
        "--preset NAME is a preset of the window (polyroll presets lists them): a race's lanes are drawn side by\n"
        "side in each frame as the window shows them, each lane's files in OUT/lane-K/; --lane K draws one lane.\n"
        "Exit codes: 0 done, 2 bad input, 3 the run diverged (frames and files are written), 130 interrupted (the\n"
        "folder it made is removed), 1 other failure (including a --video that could not be made; the frames are\n"
        "still written).");
    opts->scene.add_to(sub);
    opts->scene.add_preset_to(sub);
    sub.add_option("--out", opts->out, "folder for the frames and the run's files").required().group("Output");
    sub.add_option("--size", opts->size, "frame size WIDTHxHEIGHT in pixels (default 1280x720)").group("Output");
    sub.add_option("--fps", opts->fps, "frames per second of video, 1 to 240 (default 30)").group("Output");
    sub.add_option("--slow", opts->slow, "slow motion: K times as many frames per simulated second (default 1)")
        .group("Output");
    sub.add_option("--hold", opts->hold_s, "seconds of video the final state is held for (default 1)").group("Output");
    sub.add_flag("--follow", opts->follow, "the camera follows the polygon instead of showing the whole ramp")
        .group("Output");
    sub.add_option("--color-by", opts->colour_by, "grain colours: material (default) or speed").group("Output");
    // The same flag in British spelling, echoed as typed in its messages.
    sub.add_option_function(
           "--colour-by",
           [opts](const std::string& v) {
               opts->colour_by = v;
               opts->colour_flag = "--colour-by";
           },
           "the same as --color-by")
        .group("Output");
    sub.add_option("--video", opts->video,
                   "also encode the frames to this video file with ffmpeg (H.264: .mp4, .mkv or .mov; e.g. run.mp4); a "
                   "relative name goes into the --out folder")
        .group("Output");
    sub.add_flag("--force", opts->force, "write into an existing non-empty --out folder (old frames are removed)")
        .group("Output");
    return [opts] { return render(*opts); };
}

}  // namespace polyroll::cli
