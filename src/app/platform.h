// What differs between the sandbox as a desktop program and as a web page: one implementation of
// each function per platform, the build choosing the file (platform_desktop.cpp in the native
// build, src/web/platform_web.cpp in the WebAssembly one), so the sandbox's own code has no
// platform conditionals.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/panel_cache.h"

namespace polyroll::app {

class Window;
class LaneSet;

// Calls frame() once per displayed frame until it returns false, then done(). The desktop loops
// here and returns after done(). A page cannot loop (the browser would never draw): it hands both
// to the browser's animation frames and does not return; the caller's locals stay alive (the
// stack is not unwound), so frame() and done() may use them.
void run_frame_loop(const std::function<bool()>& frame, const std::function<void()>& done);

// Between two frames of the interactive window, `left_s` before the frame-rate cap and `idle`
// when nothing moves: the desktop sleeps (and waits for input when idle); the browser paces frames
// itself, so the page returns at once.
void rest_between_frames(Window& win, double left_s, bool idle, double idle_wait_s);

// Saves the window's back buffer as a PNG at `path` (before the swap). Throws std::runtime_error
// with the reason when it cannot (the page has no PNG export: it says to use the browser's own).
void write_screenshot(Window& win, const std::filesystem::path& path);

// After an exported run was written to `folder`: the desktop leaves it there; the page offers
// each file to the browser as a download. Returns what the panel shows as "last saved".
std::string deliver_export(const std::filesystem::path& folder);

// The page's query string (after '?', e.g. "preset=race&angle=14"); nullopt on the desktop,
// where the command line says the same.
std::optional<std::string> page_query();

// Showing a frame by copying parts of the back buffer to the window, which leaves the back buffer
// as it is: the next frame redraws only the scene and what changed in the panels, and copies only
// those, instead of the whole window. True only where the platform can and should: the desktop on a
// software GL (llvmpipe under Xvfb or in a virtual machine; GLX_MESA_copy_sub_buffer), where every
// pixel drawn or copied costs CPU. Not on the page, nor on a hardware GL, which swaps in step with
// the display and draws a frame for next to nothing. POLYROLL_PRESENT=swap turns it off.
bool can_present_parts(const std::string& gl_renderer);
// Copies `rects` (framebuffer pixels, rows from the top, of a framebuffer `height_px` tall) of the
// current context's back buffer to its window.
void present_parts(const std::vector<PanelCache::Rect>& rects, int height_px);

// After a --frames capture (the page's ?frames=N): the page prints each lane's behaviour and
// distance so far for its test (tests/web_checks.sh); the desktop prints nothing more.
void report_capture(const LaneSet& lanes);

}  // namespace polyroll::app
