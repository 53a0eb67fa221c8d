// The sandbox as a desktop program (GLFW window, threads, files): see platform.h.
#include "app/platform.h"

#include <GL/glx.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

#include "app/sandbox_window.h"
#include "render/png_writer.h"

namespace polyroll::app {

void run_frame_loop(const std::function<bool()>& frame, const std::function<void()>& done) {
    while (frame()) {
    }
    done();
}

void rest_between_frames(Window& win, double left_s, bool idle, double idle_wait_s) {
    // Without vsync (Xvfb, some drivers) do not spin a core drawing frames nobody sees.
    if (left_s > 0) std::this_thread::sleep_for(std::chrono::duration<double>(left_s));
    // Nothing moves (the run ended, or paused, and no build or run to the end under way): sleep
    // until the user does something. The timeout lets a tooltip's hover delay pass.
    if (idle) win.wait_events(idle_wait_s);
}

void write_screenshot(Window& win, const std::filesystem::path& path) {
    int w = 0, h = 0;
    const std::vector<std::uint8_t> pixels = win.read_back_buffer(w, h);
    render::write_file_whole(path, render::encode_png({pixels.data(), w, h, 4, true}));
}

std::string deliver_export(const std::filesystem::path& folder) { return folder.string(); }

std::optional<std::string> page_query() { return std::nullopt; }

namespace {

using CopySubBuffer = void (*)(Display*, GLXDrawable, int, int, int, int);

CopySubBuffer copy_sub_buffer() {
    static const auto fn = reinterpret_cast<CopySubBuffer>(
        glXGetProcAddressARB(reinterpret_cast<const GLubyte*>("glXCopySubBufferMESA")));
    return fn;
}

}  // namespace

bool can_present_parts(const std::string& gl_renderer) {
    const char* choice = std::getenv("POLYROLL_PRESENT");
    if (choice && std::strcmp(choice, "swap") == 0) return false;
    const bool software = gl_renderer.rfind("llvmpipe", 0) == 0 || gl_renderer.rfind("softpipe", 0) == 0 ||
                          gl_renderer.find("Software Rasterizer") != std::string::npos;
    Display* display = glXGetCurrentDisplay();
    if (!software || !display || !glXGetCurrentDrawable() || !copy_sub_buffer()) return false;
    const char* extensions = glXQueryExtensionsString(display, DefaultScreen(display));
    return extensions && std::strstr(extensions, "GLX_MESA_copy_sub_buffer") != nullptr;
}

void present_parts(const std::vector<PanelCache::Rect>& rects, int height_px) {
    Display* display = glXGetCurrentDisplay();
    const GLXDrawable drawable = glXGetCurrentDrawable();
    // GLX counts rows from the bottom. Each copy flushes GL first (the extension's contract).
    for (const PanelCache::Rect& r : rects)
        if (!r.empty()) copy_sub_buffer()(display, drawable, r.x0, height_px - r.y1, r.x1 - r.x0, r.y1 - r.y0);
}

void report_capture(const LaneSet& /*lanes*/) {}

}  // namespace polyroll::app
