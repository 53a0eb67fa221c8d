// polyroll-sandbox: the interactive window. Parses the flags, opens the window (or, with no display,
// hands over to the headless render), and runs the loop: physics in fixed steps at its real rate
// within a per-frame budget, the scene drawn by the project's renderer, the panels by Dear ImGui.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/controls.h"
#include "app/divergence.h"
#include "flags/parse_errors.h"
#include "app/export_files.h"
#include "app/frame_split.h"
#include "app/headless_fallback.h"
#include "app/lane_set.h"
#include "app/page_settings.h"
#include "app/physics_requests.h"
#include "app/physics_worker.h"
#include "app/platform.h"
#include "app/readouts.h"
#include "app/sandbox_physics.h"
#include "app/sandbox_presets.h"
#include "app/sandbox_settings.h"
#include "app/sandbox_state.h"
#include "app/sandbox_ui.h"
#include "app/sandbox_window.h"
#include "app/scene_view.h"
#include "render/font.h"
#include "render/changed_regions.h"
#include "render/gl_renderer.h"
#include "sim/build_info.h"
#include "sim/errors.h"
#include "sim/message_text.h"
#include "sim/scene/field_text.h"
#include "sim/scene/scene_json.h"

namespace polyroll::app {
namespace {

namespace fs = std::filesystem;
using SteadyClock = std::chrono::steady_clock;

constexpr int kExitOk = 0, kExitFailure = 1, kExitBadInput = 2;
constexpr long kMaxFrames = 10'000'000;
// Longest sleep of an idle window between frames: input wakes it at once; this bounds how late a
// tooltip or a finished background job shows.
constexpr double kIdleWaitS = 0.25;
constexpr long kDefaultBenchFrames = 600;  // 10 s at 60 frames/s: long enough for a stable mean
constexpr const char* kBenchPreset = "hexagon-large-rice";  // the largest of the experiment's scenes: the worst case

double now_s() {
    static const SteadyClock::time_point start = SteadyClock::now();
    return std::chrono::duration<double>(SteadyClock::now() - start).count();
}

struct Options {
    std::string preset;
    bool preset_given = false;   // without a display, the default scene is rendered unless a scene was chosen
    std::string screenshot;
    long frames = 0;             // 0: not given (run until closed)
    bool frames_given = false;   // an explicit --frames 0 is refused, not taken as "forever"
    bool bench = false;
    std::string theme = "projector";
    std::string out = kDefaultOutDir;
    bool out_given = false;      // without a display, the headless render's folder is --out's, or its own default
    std::string size = fmt::format("{}x{}", kDefaultWidthPx, kDefaultHeightPx);
    float ui_scale = kDefaultUiScale;
    bool follow = false;
    std::string colour_by = "material";
    std::string colour_flag = "--color-by";  // as typed, for messages: --color-by or --colour-by
    bool paused = false;
    std::string coarser = "none";  // a cheaper model picked by its key (model_budget.h), or none
    // The page's keys as flags (page_settings.h), checked as the address is: (key, value) as given.
    std::vector<std::pair<std::string, std::string>> scene_flags;
    std::string scene_file;      // --scene FILE: one lane from a scene file
    std::string layout_report;   // --layout-report FILE: the last frame's layout as JSON (the layout tests)
    // Parsed.
    int width_px = kDefaultWidthPx, height_px = kDefaultHeightPx;
    bool capture() const { return frames > 0 && !bench; }
};

// What --size accepts: "WIDTHxHEIGHT, 640..7680 by 480..4320, e.g. 1280x800".
std::string size_allowed() {
    return fmt::format("WIDTHxHEIGHT, {}..{} by {}..{}, e.g. {}x{}", kMinWidthPx, kMaxWidthPx, kMinHeightPx,
                       kMaxHeightPx, kDefaultWidthPx, kDefaultHeightPx);
}

void check(Options& o) {
    static const std::regex pattern(R"(\s*(\d{1,5})\s*[xX]\s*(\d{1,5})\s*)");
    std::smatch m;
    const std::string allowed = "allowed: " + size_allowed();
    if (!std::regex_match(o.size, m, pattern)) throw InputError(fmt::format("--size {}: not a size ({})", o.size, allowed));
    o.width_px = std::stoi(m[1]);
    o.height_px = std::stoi(m[2]);
    if (o.width_px < kMinWidthPx || o.width_px > kMaxWidthPx || o.height_px < kMinHeightPx || o.height_px > kMaxHeightPx)
        throw InputError(fmt::format("--size {}: out of range ({})", o.size, allowed));
    if (o.frames_given && (o.frames < 1 || o.frames > kMaxFrames))
        throw InputError(fmt::format("--frames {}: out of range (allowed: 1 to {})", o.frames, kMaxFrames));
    if (!o.screenshot.empty() && o.frames < 1)
        throw InputError(fmt::format("--screenshot {}: needs --frames N (the frame after which it is taken)", o.screenshot));
    if (!(o.ui_scale >= kUiScaleMin && o.ui_scale <= kUiScaleMax))
        throw InputError(fmt::format("--ui-scale {:g}: out of range (allowed: {:g} to {:g})", o.ui_scale, kUiScaleMin,
                                     kUiScaleMax));
    if (o.theme != "projector" && o.theme != "dark")
        throw InputError(fmt::format("--theme {}: unknown (allowed: projector, dark)", o.theme));
    if (o.colour_by != "material" && o.colour_by != "speed")
        throw InputError(fmt::format("{} {}: unknown (allowed: material, speed)", o.colour_flag, o.colour_by));
    if (!o.layout_report.empty() && o.frames < 1)
        throw InputError(fmt::format("--layout-report {}: needs --frames N (the frame whose layout it writes)",
                                     o.layout_report));
    if (!o.screenshot.empty()) {
        const fs::path parent = fs::absolute(o.screenshot).parent_path();
        std::error_code ec;
        if (!fs::is_directory(parent, ec))
            throw InputError(fmt::format("--screenshot {}: the folder {} does not exist", o.screenshot, parent.string()));
    }
    o.preset_given = !o.preset.empty();
    if (o.preset.empty()) o.preset = o.bench ? kBenchPreset : kDefaultSandboxPreset;
}

// Frame-time statistics for --bench.
struct BenchStats {
    std::vector<double> frame_s, physics_s, drawing_s;
    FrameSplit split_sum;  // the parts of the frames, summed
    double sim_start_s = 0.0, wall_start_s = 0.0;
    double running_wall_s = 0.0;  // wall time of the frames that began with a lane still running
    long steps = 0;
    void print(const LaneSet& lanes, double sim_end_s, double wall_end_s, const std::string& preset,
               const std::string& gl, double build_s) const {
        if (frame_s.empty() || lanes.size() == 0) return;
        std::vector<double> sorted = frame_s;
        std::sort(sorted.begin(), sorted.end());
        auto pct = [&](double p) { return sorted[std::min(sorted.size() - 1, static_cast<size_t>(p * sorted.size()))]; };
        double total = 0, phys = 0, draw = 0;
        for (double f : frame_s) total += f;
        for (double p : physics_s) phys += p;
        for (double d : drawing_s) draw += d;
        const double n = static_cast<double>(frame_s.size());
        int grains = 0;
        for (size_t i = 0; i < lanes.size(); ++i) grains += lanes.lane(i).grains();
        const double sim = sim_end_s - sim_start_s, wall = wall_end_s - wall_start_s;
        // The real-time ratio counts only the frames in which something was still running.
        const double rt_wall = running_wall_s > 0 ? running_wall_s : wall;
        fmt::print("polyroll-sandbox --bench: {}, {} lane(s), {} grains, fidelity {}, GL {}\n", preset,
                   lanes.size(), grains, lanes.lane(0).scene().fidelity.preset, gl);
        fmt::print("  build        {:.2f} s (pouring and settling, on a worker thread)\n", build_s);
        fmt::print("  frames       {} in {:.2f} s: {:.1f} frames/s\n", frame_s.size(), wall, n / wall);
        fmt::print("  frame time   mean {:.2f} ms, median {:.2f} ms, 95th percentile {:.2f} ms, max {:.2f} ms\n",
                   1e3 * total / n, 1e3 * pct(0.5), 1e3 * pct(0.95), 1e3 * sorted.back());
        fmt::print("  physics      {:.2f} ms per frame (budget {:.0f} ms, beside the drawing), {} tracker steps\n",
                   1e3 * phys / n, 1e3 * kPhysicsBudgetPerFrameS, steps);
        fmt::print("  drawing      {:.2f} ms per frame (scene draw list, GL, ImGui, swap)\n", 1e3 * draw / n);
        print_split(split_sum, n);
        fmt::print("  simulated    {:.3f} s in {:.2f} s of wall time while running: {:.2f}x real time (physics alone "
                   "{:.2f}x){}\n",
                   sim, rt_wall, sim / rt_wall, phys > 0 ? sim / phys : 0.0,
                   lanes.all_finished() ? ", then the run ended" : "");
        const bool met = n / wall >= 59.0 && sim / rt_wall >= kKeepingUpShare;
        // The target for every bundled preset under Xvfb (docs/sandbox.md, Speed): real time at 50 frames/s or
        // more.
        const bool met_50 = n / wall >= 50.0 && sim / rt_wall >= kKeepingUpShare;
        fmt::print("  target       60 frames/s at real time: {}; real time at 50 frames/s or more: {}\n",
                   met ? "met" : "not met", met_50 ? "met" : "not met");
    }
};

// The window's loop on the UI thread. The physics (lanes, clock, transport) lives in SandboxPhysics and
// is changed only by jobs on the one physics worker: this class fills PhysicsRequests, hands them
// over, and learns what happened from each job's PhysicsOutcome; it reads the lanes to draw them
// only while the worker is idle.
class Sandbox {
public:
    Sandbox(Window& win, SandboxState state, const Options& o)
        : win_(win), s_(std::move(state)), o_(o), physics_(o.capture(), now_s) {
        ctx_.lanes = &physics_.lanes();
        ctx_.clock = &physics_.clock();
        ctx_.budget = &physics_.budget_choice();
        ctx_.budget_offer = &physics_.budget_offer();
    }

    int run() {
        pending_.model_level = s_.model_level;  // --coarser
        apply_controls();
        pending_.play = s_.playing;  // --paused
        // A capture or a benchmark starts from the built scene, whatever the machine's speed.
        const bool wait = o_.capture() || o_.bench;
        pending_.wait_until_built = wait;
        const double build_start_s = now_s();
        take(worker_.run(std::exchange(pending_, {})));
        const double build_s = wait ? now_s() - build_start_s : 0.0;
        if (wait && last_.build_failed) {
            fmt::print(stderr, "polyroll-sandbox: the scene could not be built: {}\n", lanes().build_error());
            return kExitFailure;
        }
        // The loop's own state lives on the heap, shared by its two steps: a page's frame loop
        // (platform.h) runs them from the browser after this function's stack frame is gone.
        struct LoopState {
            long frames = 0;
            BenchStats bench;
            double last = 0.0;
            long frame = 0;
            double build_s = 0.0;
        };
        const auto loop = std::make_shared<LoopState>();
        loop->frames = o_.bench && o_.frames < 1 ? kDefaultBenchFrames : o_.frames;
        loop->build_s = build_s;
        loop->bench.wall_start_s = now_s();
        loop->last = now_s();
        // One frame; false once the window closes or the capture's last frame is done.
        const auto one_frame = [this, loop]() -> bool {
            const long frames = loop->frames;
            BenchStats& bench = loop->bench;
            double& last = loop->last;
            long& frame = loop->frame;
            if (win_.should_close()) return false;
            const double t0 = now_s();
            const double wall_dt = frame == 0 ? 0.0 : t0 - last;
            last = t0;
            const bool final_frame = frames > 0 && frame + 1 >= frames;
            const bool was_running = lanes().ready() && !last_.run_over();
            const FrameTimes times = frame_once(wall_dt, final_frame);
            ++frame;
            if (o_.bench) {
                bench.frame_s.push_back(now_s() - t0);
                if (was_running) bench.running_wall_s += now_s() - t0;
                bench.physics_s.push_back(times.physics_s);
                bench.drawing_s.push_back(times.drawing_s);
                bench.split_sum += times.split;
            }
            if (final_frame) return false;
            if (!o_.capture() && !o_.bench) {
                const double left = 1.0 / kFrameRateCapHz - (now_s() - t0);
                const bool moving = !lanes().ready() || last_.running_to_end || (s_.playing && !last_.run_over());
                rest_between_frames(win_, left, !moving, kIdleWaitS);
            }
            return true;
        };
        const auto after_frames = [this, loop] {
            const long frames = loop->frames;
            BenchStats& bench = loop->bench;
            const double build_s = loop->build_s;
            if (o_.bench) {
                // The budget may have rebuilt the scene coarser during the bench: report the built lanes.
                if (!lanes().ready() && !last_.build_failed) {
                    pending_.wait_until_built = true;
                    take(worker_.run(std::exchange(pending_, {})));
                }
                bench.steps = steps_;
                bench.print(lanes(), last_.time_s, now_s(),
                            s_.scene_file.empty() ? "preset " + s_.preset : "scene file " + s_.scene_file,
                            win_.gl_renderer(), build_s);
                fmt::print("  shown by     {}\n",
                           win_.keeps_panels()
                               ? fmt::format("drawing and copying only what changed, of the scene and the panels (a "
                                             "software GL: GLX_MESA_copy_sub_buffer; POLYROLL_PRESENT=swap swaps and "
                                             "draws whole frames instead); the scene drawn over {:.0f}% of its pixels a "
                                             "frame on average",
                                             scene_frames_ > 0 ? 100.0 * scene_share_sum_ / scene_frames_ : 100.0)
                               : "swapping the whole frame");
                fmt::print("  model        {}\n", budget_statement(physics_.budget_choice(), physics_.budget_offer(),
                                                                   budget_figures()));
            }
            if (o_.capture()) {
                // "--fill 0" on the default preset is not the default preset any more: say so.
                fmt::print("polyroll-sandbox: {} frames of {}{} ({:.2f} s simulated{}){}\n", frames,
                           s_.scene_file.empty() ? "preset " + s_.preset : "scene file " + s_.scene_file,
                           o_.scene_flags.empty() ? "" : " as the flags changed it",
                           last_.time_s, last_.trouble ? ", stopped by numerical trouble" : "",
                           o_.screenshot.empty() ? "" : fmt::format(", screenshot {}", o_.screenshot));
                if (lanes().trouble()) fmt::print("  {}\n", *lanes().trouble());
                report_capture(lanes());
            }
        };
        run_frame_loop(one_frame, after_frames);
        return kExitOk;
    }

private:
    struct FrameTimes {
        double physics_s = 0.0;  // on the physics worker
        double drawing_s = 0.0;  // on this thread, meanwhile
        FrameSplit split;        // the parts (--bench)
    };

    // Read only while the worker is idle (between a job's finish and the next start).
    const LaneSet& lanes() const { return physics_.lanes(); }

    // One window frame. The panel is built first (it reads the lanes), then the lanes' snapshots are
    // taken; from there the frame's physics job runs on the worker while this thread draws the
    // snapshots, renders the panel and swaps, which read nothing the physics writes. The two meet
    // (the sync point) before the panel's requests are handed over. A frame thus shows the state its
    // physics started from (one frame of lag, 1/60 s), and a slow scene's physics and the drawing
    // share the frame's time instead of taking turns. A capture (--frames) runs its frame's job
    // first instead and waits for it, so that its last frame shows the moment its frame count
    // promises.
    FrameTimes frame_once(double wall_dt, bool final_frame) {
        const bool screenshot_after = final_frame && !o_.screenshot.empty();
        // The scale shown fits the window (the size of the last frame; the asked size before the first).
        const ImVec2 last_size = ImGui::GetIO().DisplaySize;
        const float scale = fitted_ui_scale(s_.ui_scale, last_size.x > 0 ? last_size.x : static_cast<float>(o_.width_px),
                                            last_size.y > 0 ? last_size.y : static_cast<float>(o_.height_px));
        ctx_.ui_scale_shown = scale;
        win_.set_ui_scale(scale);
        win_.set_high_contrast(s_.high_contrast);
        FrameTimes times;
        FrameSplit& split = times.split;
        const double p0 = now_s();
        win_.begin_frame();
        split.panels_s = now_s() - p0;
        if (o_.capture()) times.physics_s = take(worker_.run(frame_requests(wall_dt)));
        const double p1 = now_s();

        const ImGuiIO& io = ImGui::GetIO();
        const UiLayout L = ui_layout(io.DisplaySize.x, io.DisplaySize.y, scale);
        UiRequests req;
        read_shortcuts(s_, req);
        ctx_.running_to_end = last_.running_to_end;
        ctx_.capture = o_.capture();
        ctx_.run_over = lanes().ready() && last_.run_over() && !last_.running_to_end;
        ctx_.large_font = win_.large_font();
        // The layout is reported for the capture's last frame (--layout-report).
        UiLayoutReport report;
        UiLayoutReport* const rep = final_frame && !o_.layout_report.empty() ? &report : nullptr;
        draw_control_panel(s_, ctx_, L, req, rep);
        draw_readouts_and_plots(s_, ctx_, L, rep);
        const float top = draw_status(s_, ctx_, L, rep);
        split.panels_s += now_s() - p1;

        int fb_w = 0, fb_h = 0;
        win_.framebuffer_size(fb_w, fb_h);
        const float ratio = win_.pixel_ratio();
        // The scene fills the rest, below the status band (so it never covers a ramp's start), a seam
        // away from the panels beside it (panel_seam_px).
        const float seam = panel_seam_px(ratio);
        const render::PxRect area{L.panel_w * ratio + seam, top * ratio + seam,
                                  std::max(1.0f, (L.width - L.panel_w) * ratio - seam),
                                  std::max(1.0f, (L.height - L.plots_h - top) * ratio - 2.0f * seam)};
        handle_mouse(area, ratio);
        const double s0 = now_s();
        take_snapshots();
        split.snapshots_s = now_s() - s0;
        const bool show_scene = !last_.running_to_end;
        const bool any_active = ImGui::IsAnyItemActive();

        if (!o_.capture()) worker_.start(frame_requests(wall_dt));
        const double d0 = now_s();
        SceneViewBoxes boxes;
        draw_scene(fb_w, fb_h, area, ratio, scale, show_scene, rep ? &boxes : nullptr, split);
        if (rep) write_layout_report(L, *rep, area, ratio, boxes);
        const double u0 = now_s();
        win_.render_ui(panel_background(), area, scene_changed_ ? &*scene_changed_ : nullptr);
        // The benchmark waits for GL after each part so that each is charged its own rasterising
        // (a software GL rasterises when flushed, so otherwise the swap would pay for everything).
        if (o_.bench) win_.finish_gl();
        split.panels_gl_s = now_s() - u0;
        if (screenshot_after) write_screenshot(win_, o_.screenshot);
        if (req.screenshot) save_screenshot();
        const double w0 = now_s();
        win_.swap();
        split.swap_s = now_s() - w0;
        times.drawing_s = now_s() - d0;
        if (!o_.capture()) times.physics_s = take(worker_.finish());  // rethrows what the physics threw
        split.physics_wait_s = now_s() - d0 - times.drawing_s;
        split.physics_s = times.physics_s;
        carry_out(req, any_active);
        return times;
    }

    // A frame's job: the commands pending so far (a lane found not finite) and the frame itself.
    PhysicsRequests frame_requests(double wall_dt) {
        PhysicsRequests r = std::exchange(pending_, {});
        r.frame = PhysicsRequests::Frame{wall_dt, kSlowMotionDivisors[static_cast<size_t>(s_.slow_index)]};
        return r;
    }

    // Reads a job's outcome: the panel shows the transport the physics reports. Returns the job's
    // wall time.
    double take(const PhysicsOutcome& out) {
        last_ = out;
        s_.playing = out.playing;
        steps_ += out.steps;
        return out.physics_s;
    }

    void handle_mouse(const render::PxRect& area, float ratio) {
        const ImGuiIO& io = ImGui::GetIO();
        if (io.WantCaptureMouse) return;
        const render::Px at{io.MousePos.x * ratio, io.MousePos.y * ratio};
        const bool inside = at.x >= area.x && at.x < area.x + area.width && at.y >= area.y && at.y < area.y + area.height;
        if (!inside) return;
        if (io.MouseWheel != 0.0f) view_.zoom_at(at, std::pow(1.15, static_cast<double>(io.MouseWheel)), area);
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f))
            view_.pan_by(io.MouseDelta.x * ratio, io.MouseDelta.y * ratio);
    }

    // The lanes' snapshots for this frame's picture (the lanes' names are in the status band). The last
    // finite snapshots are kept: a lane whose state turns to NaN stops the run (requested of the
    // physics before it steps again), and the picture stays the last sound one rather than garbage.
    void take_snapshots() {
        const LaneSet& lanes = this->lanes();
        if (lanes.ready() && !last_.running_to_end) {
            shown_.resize(lanes.size());
            for (size_t i = 0; i < lanes.size(); ++i) {
                render::Snapshot snap = lanes.lane(i).snapshot();
                if (snapshot_finite(snap)) shown_[i] = std::move(snap);
                else if (!pending_.non_finite_lane) pending_.non_finite_lane = i;
            }
        } else if (!lanes.ready()) {
            shown_.clear();
        }
    }

    // Reads only the snapshots and the view: it runs while the physics worker steps the lanes.
    void draw_scene(int fb_w, int fb_h, const render::PxRect& area, float ratio, float scale, bool show_scene,
                    SceneViewBoxes* boxes, FrameSplit& split) {
        const float unit = scale * ratio;
        if (!atlas_ || atlas_unit_ != unit) {
            drawn_.reset();  // it points at the atlas about to go
            atlas_ = std::make_unique<render::FontAtlas>(render::find_font_dir(), scene_view_fonts(unit));
            atlas_unit_ = unit;
        }
        SceneViewOptions vo;
        vo.width_px = fb_w;
        vo.height_px = fb_h;
        vo.area = area;
        vo.unit = unit;
        vo.follow = s_.follow;
        vo.colouring = s_.colouring;
        vo.colour_speed_max_m_s = kDefaultColourSpeedMax_m_s;
        vo.view = view_;
        vo.close_up_lane = s_.selected_lane;
        vo.area_only = win_.keeps_panels();
        const std::vector<render::Snapshot> none;
        const double t0 = now_s();
        render::DrawList list = build_scene_view(show_scene ? shown_ : none, vo, *atlas_, boxes);
        // Where the back buffer still holds the last frame, the scene is drawn only where its list
        // changed, and where the panels drew over it last frame (render/changed_regions.h).
        scene_changed_.reset();
        std::vector<render::LayerPixels> pixels;  // measured once for the regions' growth and the drawing
        if (drawn_ && win_.holds_last_frame()) {
            scene_changed_ = render::changed_regions(*drawn_, list);
            if (scene_changed_) {
                for (const render::ClipRect& r : win_.panels_in_scene()) render::add_region(*scene_changed_, r);
                pixels = render::pixels_of(list);
                render::hold_whole_discs(list, pixels, *scene_changed_);
            }
        }
        const double t1 = now_s();
        if (scene_changed_) gl_.draw(list, *scene_changed_, pixels);
        else gl_.draw(list);
        // For --bench: the share of the scene's pixels drawn (regions may overlap: at most all).
        double share = 1.0;
        if (scene_changed_ && list.bounds && !list.bounds->empty()) {
            double drawn_px = 0.0;
            for (const render::ClipRect& r : *scene_changed_) {
                const render::ClipRect in = render::intersection(r, *list.bounds);
                drawn_px += static_cast<double>(in.width) * in.height;
            }
            share = std::min(1.0, drawn_px / (static_cast<double>(list.bounds->width) * list.bounds->height));
        }
        scene_share_sum_ += share;
        ++scene_frames_;
        drawn_ = std::move(list);
        if (o_.bench) win_.finish_gl();
        split.scene_list_s = t1 - t0;
        split.scene_gl_s = now_s() - t1;
    }

    // The frame's layout as JSON, in window coordinates (the scene's boxes divided by the pixel
    // ratio): what tests/test_sandbox_smoke.cpp checks for text cut off or covering the ramps.
    void write_layout_report(const UiLayout& L, const UiLayoutReport& r, const render::PxRect& area, float ratio,
                             const SceneViewBoxes& b) const {
        using json = nlohmann::ordered_json;
        auto box = [](float x0, float y0, float x1, float y1) { return json::array({x0, y0, x1, y1}); };
        auto px = [&](const render::PxRect& p) {
            return box(p.x / ratio, p.y / ratio, (p.x + p.width) / ratio, (p.y + p.height) / ratio);
        };
        json j;
        j["width"] = L.width;
        j["height"] = L.height;
        j["ui_scale"] = s_.ui_scale;
        j["ui_scale_shown"] = ctx_.ui_scale_shown;
        j["font_px"] = kBaseFontPx * ctx_.ui_scale_shown;
        for (const auto& [key, list] : {std::pair{"windows", &r.windows}, std::pair{"contents", &r.contents},
                                        std::pair{"plots", &r.plots}}) {
            json o = json::object();
            for (const LayoutBox& w : *list) o[w.name] = box(w.x0, w.y0, w.x1, w.y1);
            j[key] = o;
        }
        j["scene"] = px(area);
        j["ramp_starts"] = json::array();
        for (const render::Px& p : b.ramp_starts) j["ramp_starts"].push_back({p.x / ratio, p.y / ratio});
        for (const auto& [key, list] : {std::pair{"badges", &b.badges}, std::pair{"close_up", &b.close_up}}) {
            j[key] = json::array();
            for (const render::PxRect& p : *list) j[key].push_back(px(p));
        }
        std::ofstream(o_.layout_report) << j.dump(1) << "\n";
    }

    // The controls' scenes, requested of the physics as a restart (or the reason they were refused).
    void apply_controls() {
        try {
            pending_.restart_with = scenes_for(s_);
            ctx_.control_error.clear();
        } catch (const std::exception& e) {
            ctx_.control_error = fmt::format("Not applied: {}", e.what());
        }
        s_.changes_pending = false;
    }

    void save_screenshot() {
        try {
            fs::create_directories(o_.out);
            const fs::path p = next_numbered(o_.out, "screenshot", ".png");
            write_screenshot(win_, p);
            say(fmt::format("Saved the screenshot: {}", p.string()));
        } catch (const std::exception& e) {
            say(fmt::format("The screenshot failed: {}", e.what()));
        }
    }

    void export_run() {
        if (!lanes().ready()) return;
        try {
            fs::create_directories(o_.out);
            std::vector<RunResult> runs;
            for (size_t i = 0; i < lanes().size(); ++i) runs.push_back(lanes().lane(i).result());
            const fs::path folder = next_numbered(o_.out, "run", "");
            export_runs(folder, runs);
            say("Saved the run: " + deliver_export(folder));
        } catch (const std::exception& e) {
            say(fmt::format("The export failed: {}", e.what()));
        }
    }

    // A confirmation over the scene, where the eye is, for kFeedbackShowS.
    void say(std::string text) {
        ctx_.feedback = std::move(text);
        ctx_.feedback_until_s = ImGui::GetTime() + kFeedbackShowS;
    }

    // At the sync point: the panel's requests become commands for the physics, handed over at once
    // and waited for (the physics is idle now), so the next frame's panel shows their effect.
    void carry_out(const UiRequests& req, bool any_item_active) {
        if (req.load_preset) {
            try {
                load_preset(s_, *req.load_preset);
                // A cheaper model picked for one scene is not carried to the next: a preset plays as asked.
                s_.model_level = -1;
                pending_.model_level = -1;
                view_.reset();
                apply_controls();
            } catch (const std::exception& e) {
                ctx_.control_error = e.what();
            }
        }
        if (req.controls_changed) s_.changes_pending = true;
        if (req.model_level_changed) {
            pending_.model_level = s_.model_level;
            apply_controls();
        }
        // A slider applies when it is let go, not at every pixel of the drag.
        if (s_.changes_pending && s_.restart_on_change && !any_item_active) apply_controls();
        if (req.reset) apply_controls();
        if (req.toggle_play) {
            // Play after the run is over starts it again; a restart already asked for is not over.
            if (!pending_.restart_with && last_.run_over()) {
                apply_controls();
                pending_.play = true;
            } else {
                pending_.play = !s_.playing;
            }
        }
        if (req.step) pending_.step = true;
        if (req.run_to_end) pending_.run_to_end = true;
        if (pending_.has_commands()) take(worker_.run(std::exchange(pending_, {})));
        if (req.export_run) export_run();
        if (req.reset_view) view_.reset();
    }

    Window& win_;
    SandboxState s_;
    Options o_;
    SandboxPhysics physics_;
    UiContext ctx_;
    ViewTransform view_;
    render::GlRenderer gl_;
    std::unique_ptr<render::FontAtlas> atlas_;
    float atlas_unit_ = 0.0f;
    std::optional<render::DrawList> drawn_;  // the scene's list as the back buffer holds it
    // This frame's: where the scene was drawn, when only where it changed (none: drawn whole).
    std::optional<std::vector<render::ClipRect>> scene_changed_;
    double scene_share_sum_ = 0.0;  // the share of the scene's pixels drawn, summed over frames
    long scene_frames_ = 0;
    std::vector<render::Snapshot> shown_;
    PhysicsRequests pending_;  // commands gathered since the last hand-off
    PhysicsOutcome last_;      // what the last job reported
    long steps_ = 0;
    // Last, so it is destroyed first: it finishes a job in hand before physics_ goes.
    PhysicsWorker worker_{[this](const PhysicsRequests& r) { return physics_.run(r); }};
};

// The web page's address (?preset=race&frames=240): what the command line would say. Nothing on the desktop.
std::optional<PageSettings> page_settings(Options& o) {
    const std::optional<std::string> query = page_query();
    if (!query) return std::nullopt;
    PageSettings page = parse_page_query(*query);
    if (page.preset) o.preset = *page.preset;
    if (page.frames) {
        o.frames = *page.frames;
        o.frames_given = true;
    }
    o.paused = o.paused || page.paused;
    o.bench = o.bench || page.bench;
    return page;
}

namespace {

// The words the flags' help and errors use, and the page's address keys as flags with their values.
struct FlagTexts {
    std::string presets_list, levels_list;
    std::vector<std::string> page_flags;                           // their keys, without the dashes
    std::map<std::string, std::string> values;                     // key -> as typed
};

// What --help shows after a scene flag, as the command line's typed flags show it.
std::string flag_type_name(const SceneField& f) {
    switch (f.type) {
        case FieldType::integer: return "INT";
        case FieldType::seed: return "UINT";
        case FieldType::number:
        case FieldType::optional_number: return "FLOAT";
        case FieldType::preset:
        case FieldType::choice: break;
    }
    return "TEXT";
}

void add_flags(CLI::App& cli, Options& o, FlagTexts& t) {
    for (const std::string& n : sandbox_preset_names()) t.presets_list += (t.presets_list.empty() ? "" : ", ") + n;
    cli.add_option("--preset", o.preset, "sandbox preset (assets/sandbox-presets.json): " + t.presets_list);
    cli.add_option("--screenshot", o.screenshot, "save the window as a PNG after --frames frames, then exit");
    cli.add_option("--frames", o.frames,
                   "run this many frames, then exit; each advances 1/60 s of simulated time (a capture shows the "
                   "same moment on any machine)");
    cli.add_flag("--bench", o.bench,
                 "time the window's frames at real time (default preset hexagon-large-rice, 600 frames) and print "
                 "the frame times");
    cli.add_option("--out", o.out,
                   fmt::format("folder for screenshots (S) and exported runs (E) (default {}); without a display, "
                               "for the headless render's frames (default {})",
                               kDefaultOutDir, kHeadlessOutDir));
    cli.add_option("--size", o.size,
                   fmt::format("window size WIDTHxHEIGHT (default {}x{})", kDefaultWidthPx, kDefaultHeightPx));
    cli.add_option("--ui-scale", o.ui_scale,
                   fmt::format("size of text and controls, {:g} to {:g} (default {:g})", kUiScaleMin, kUiScaleMax,
                               kDefaultUiScale));
    cli.add_flag("--follow", o.follow, "the camera follows the polygon instead of showing the whole ramp");
    cli.add_option("--color-by", o.colour_by, "grain colours: material (default) or speed");
    // The same flag in British spelling, echoed as typed in its messages.
    cli.add_option_function<std::string>(
        "--colour-by",
        [&o](const std::string& v) {
            o.colour_by = v;
            o.colour_flag = "--colour-by";
        },
        "the same as --color-by");
    cli.add_flag("--paused", o.paused, "start paused");
    // The scene fields the page's address takes, as flags of the same names from the field table
    // (page_settings.h: every field with a flag and a panel control), checked by the same code.
    for (const SceneField* f : window_scene_fields()) {
        const std::string key = field_key(*f);
        t.page_flags.push_back(key);
        std::string help = field_help(*f);
        // The model's list offers what the window runs (not the 3D reference, a minute a run).
        if (const ControlRow& row = control_row(f->path); row.offered)
            help += "; the window runs " + comma_list(row.offered());
        cli.add_option("--" + key, t.values[key], help)->group("Scene")->type_name(flag_type_name(*f));
    }
    cli.add_option("--scene", o.scene_file, "a scene file (JSON, as polyroll run --scene reads it): one lane; the flags "
                                            "above apply over it")
        ->group("Scene");
    t.levels_list = "none";
    for (const BudgetLevel& l : budget_figures().levels) t.levels_list += ", " + level_key(l);
    cli.add_option("--coarser", o.coarser,
                   fmt::format("step a cheaper model than the scene asks, as the panel offers it: {} (default none; "
                               "grains 2x larger of the same fill mass, ...; the errors are in the panel)",
                               t.levels_list));
    cli.add_option("--layout-report", o.layout_report,
                   "with --frames: write the last frame's layout (the panels' boxes and what they hold, the ramps' "
                   "start, the lanes' badges) as JSON, for the layout tests");
    cli.set_version_flag("--version", version_text("polyroll-sandbox"), "print the version, Box2D's and the build type");
    cli.add_option("--theme", o.theme,
                   "panel colours: projector (default; dark text on pale panels, strong borders) or dark (ImGui's)");
}

// Parses the flags into `o`; an exit code where the program stops here (help, version, a bad flag).
std::optional<int> parse_flags(CLI::App& cli, int argc, char** argv, Options& o, FlagTexts& t) {
    try {
        cli.parse(argc, argv);
        o.frames_given = cli.count("--frames") > 0;
        o.out_given = cli.count("--out") > 0;
        for (const std::string& key : t.page_flags)
            if (cli.count("--" + key) > 0) o.scene_flags.emplace_back(key, t.values[key]);
    } catch (const CLI::CallForHelp& e) {
        return cli.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return cli.exit(e);
    } catch (const CLI::ParseError& e) {
        // In the program's words, as polyroll's flags answer ("--ui-scale abc: not a number (allowed: 0.75 to
        // 2.5)"), not CLI11's "Could not convert: --ui-scale = abc".
        const std::map<std::string, std::string> allowed = {
            {"--ui-scale", fmt::format("{:g} to {:g}", kUiScaleMin, kUiScaleMax)},
            {"--frames", fmt::format("1 to {}", kMaxFrames)},
            {"--size", size_allowed()},
            {"--preset", t.presets_list},
            {"--theme", "projector, dark"},
            {"--color-by", "material, speed"},
            {"--colour-by", "material, speed"},
            {"--coarser", t.levels_list}};
        fmt::print(stderr, "polyroll-sandbox: {}\n",
                   printable_line(flags::flag_error_text(e, cli, "polyroll-sandbox", allowed)));
        return kExitBadInput;
    }
    return std::nullopt;
}

// The window's first state: the preset or scene file, then the page's settings and flags over it.
// Checks the flags and fills in what they imply (the window size); throws InputError naming a bad value.
SandboxState initial_state(Options& o) {
    const std::optional<PageSettings> page = page_settings(o);
    const PageSettings flags = parse_window_flags(o.scene_flags);
    if (!o.scene_file.empty() && !o.preset.empty())
        throw InputError(fmt::format("--scene {} and --preset {}: both given (allowed: one of them)", o.scene_file,
                                     o.preset));
    check(o);
    SandboxState state = o.scene_file.empty() ? state_for_preset(o.preset) : state_for_scene_file(o.scene_file);
    if (page) apply_page_settings(*page, state);
    apply_page_settings(flags, state);
    state.model_level = level_from_key(o.coarser, budget_figures());
    state.follow = o.follow;
    state.colouring = o.colour_by == "speed" ? render::GrainColouring::speed : render::GrainColouring::material;
    state.ui_scale = o.ui_scale;
    state.playing = !o.paused;
    state.high_contrast = o.theme == "projector";
    return state;
}

// Without a display: the default scene, or the first lane of the one the flags chose (a render draws
// one scene; the --coarser model is the window's budget, not the render's, which is not real time).
HeadlessScene headless_scene(const Options& o, const SandboxState& state) {
    HeadlessScene shown;
    if (!o.preset_given && o.scene_file.empty() && o.scene_flags.empty()) return shown;
    const std::vector<Scene> scenes = scenes_for(state);
    shown.scene_json = scene_to_json(scenes.front()).dump(2) + "\n";
    const std::string source = !state.preset.empty()       ? "preset " + state.preset
                               : !state.scene_file.empty() ? "scene file " + state.scene_file
                                                           : "the default scene";
    const std::string flags = o.scene_flags.empty() ? "" : " as the flags changed it";
    const std::string lane =
        scenes.size() > 1 ? fmt::format(", lane 1 of {}: a render draws one", scenes.size()) : std::string();
    shown.what = fmt::format("the chosen scene ({}{}{})", source, flags, lane);
    return shown;
}

}  // namespace

int sandbox_main(int argc, char** argv) {
    Options o;
    CLI::App cli{"polyroll-sandbox: the interactive sandbox. Pick a polygon, drag the fill slider, and watch it stop "
                 "or roll to the end, with the speed and energy plotted live; race up to four polygons side by side."};
    cli.footer(
        shortcut_help() + "\n" +
        "Without a display it renders its scene headless instead (polyroll render: the default scene, or the\n"
        "first lane of the one --preset, --scene or the scene flags chose) into --out, or runs/default; a\n"
        "folder that already holds files is left as it is and a new numbered one used (DIR-2).\n"
        "Examples:\n"
        "  polyroll-sandbox\n"
        "  polyroll-sandbox --preset octagon-rice\n"
        "  polyroll-sandbox --screenshot shot.png --frames 240   # run 240 frames, save the window, exit\n"
        "  xvfb-run -a -s \"-screen 0 1280x800x24\" polyroll-sandbox --bench\n"
        "Exit codes: 0 done, 2 bad input, 1 anything else (including no display for --screenshot or --bench).");
    FlagTexts texts;
    add_flags(cli, o, texts);
    if (const std::optional<int> stop = parse_flags(cli, argc, argv, o, texts)) return *stop;
    SandboxState state;
    try {
        state = initial_state(o);
    } catch (const InputError& e) {
        fmt::print(stderr, "polyroll-sandbox: {}\n", printable_line(e.what()));
        return kExitBadInput;
    }

    std::string why;
    std::unique_ptr<Window> win = Window::open(o.width_px, o.height_px, !(o.capture() || o.bench), why);
    if (!win) {
        if (o.capture() || o.bench) {
            fmt::print(stderr, "polyroll-sandbox: no display ({}); --screenshot, --frames and --bench need one: run under "
                               "xvfb-run -a -s \"-screen 0 1280x800x24\"\n",
                       why);
            return kExitFailure;
        }
        HeadlessScene shown;
        try {
            shown = headless_scene(o, state);
        } catch (const InputError& e) {  // a chosen combination out of range
            fmt::print(stderr, "polyroll-sandbox: {}\n", printable_line(e.what()));
            return kExitBadInput;
        }
        return run_headless_instead(why, o.out_given ? o.out : std::string(kHeadlessOutDir), shown);
    }
    // On the heap: a page's frame loop keeps using it after this function's stack frame is gone.
    const auto app = std::make_unique<Sandbox>(*win, std::move(state), o);
    return app->run();
}

}  // namespace
}  // namespace polyroll::app

int main(int argc, char** argv) {
    try {
        return polyroll::app::sandbox_main(argc, argv);
    } catch (const std::exception& e) {
        fmt::print(stderr, "polyroll-sandbox: {}\n", polyroll::printable_line(e.what()));
        return 1;
    }
}
