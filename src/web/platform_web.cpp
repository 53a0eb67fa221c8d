// The sandbox as a web page (WebAssembly, WebGL 2, no threads, no files): see app/platform.h.
#include "app/platform.h"

#include <emscripten.h>

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "app/lane_set.h"
#include "sim/measurements.h"
#include "sim/scene/scene_json.h"

namespace polyroll::app {

namespace {

// The loop's two steps, kept here while the browser calls tick() once per animation frame.
std::function<bool()> g_frame;
std::function<void()> g_done;
bool g_first_frame_told = false;

void tick() {
    const bool more = g_frame();
    if (!g_first_frame_told) {
        g_first_frame_told = true;
        // index.html takes the time from load to the first frame here and hides its loading note.
        EM_ASM({ if (Module.onFirstFrame) Module.onFirstFrame(); });
    }
    if (!more) {
        emscripten_cancel_main_loop();
        g_done();
        EM_ASM({ if (Module.onFramesDone) Module.onFramesDone(); });
    }
}

}  // namespace

void run_frame_loop(const std::function<bool()>& frame, const std::function<void()>& done) {
    g_frame = frame;
    g_done = done;
    // Frames per second 0: the browser's own rate (requestAnimationFrame), for people. A page that
    // asks for timers instead (index.html does for ?frames=N) runs its frames on setTimeout, which a
    // headless browser's virtual time drives as fast as the machine draws. true: does not return
    // (the caller keeps its heap objects; its stack is unwound without destructors).
    const int fps = EM_ASM_INT({ return Module.frameTimerHz || 0; });
    emscripten_set_main_loop(tick, fps, true);
}

void rest_between_frames(Window& /*win*/, double /*left_s*/, bool /*idle*/, double /*idle_wait_s*/) {}

void write_screenshot(Window& /*win*/, const std::filesystem::path& /*path*/) {
    throw std::runtime_error("not available in the browser: use the browser's own screenshot");
}

std::string deliver_export(const std::filesystem::path& folder) {
    // The run's files were written to the page's memory file system; each goes to the browser as a
    // download named after its folder ("run-001-summary.json", "run-001-lane-2-trajectory.csv").
    int count = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
        if (!entry.is_regular_file()) continue;
        std::ifstream in(entry.path(), std::ios::binary);
        const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        std::string name = std::filesystem::relative(entry.path(), folder.parent_path()).string();
        for (char& c : name)
            if (c == '/') c = '-';
        EM_ASM({ Module.downloadFile(UTF8ToString($0), HEAPU8.subarray($1, $1 + $2)); }, name.c_str(), bytes.data(),
               bytes.size());
        ++count;
    }
    return fmt::format("{} downloaded ({} files)", folder.filename().string(), count);
}

std::optional<std::string> page_query() {
    return std::string(emscripten_run_script_string("window.location.search"));
}

bool can_present_parts(const std::string& /*gl_renderer*/) { return false; }  // WebGL shows whole frames

void present_parts(const std::vector<PanelCache::Rect>& /*rects*/, int /*height_px*/) {}

void report_capture(const LaneSet& lanes) {
    // One line a lane, read by tests/web_checks.sh (the page's output shows it).
    for (size_t i = 0; i < lanes.size(); ++i) {
        const Measurements& m = lanes.lane(i).measured();
        fmt::print("polyroll-web: lane {}: behaviour {}, distance {:.6f} m at {:.4f} s\n", i + 1,
                   to_string(m.behaviour), m.distance_m, lanes.lane(i).time_s());
        // The first face impact: what the page and the native run share even where a tipping point
        // later sends them apart (the default scene: tests/web_checks.sh).
        if (!m.impacts.empty()) {
            const FaceImpact& f = m.impacts.front();
            fmt::print("polyroll-web: lane {} first impact: time {:.6f} s, position {:.6f} m, kinetic before {:.9g} J\n",
                       i + 1, f.time_s, f.position_m, f.kinetic_before_J);
        }
        // The lane's whole scene, so the test runs the same one natively (polyroll run --scene).
        fmt::print("polyroll-web: lane {} scene {}\n", i + 1, scene_to_json(lanes.lane(i).scene()).dump());
    }
    std::fflush(stdout);
}

}  // namespace polyroll::app
