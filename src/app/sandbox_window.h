// The sandbox's window: GLFW with an OpenGL 3.3 core context, Dear ImGui on it (its GLFW and
// OpenGL3 backends from Debian's libimgui), DejaVu fonts at the chosen UI scale, the projector theme,
// and reading the back buffer for screenshots. Links the system GL, never OSMesa.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "app/panel_cache.h"
#include "render/colour.h"
#include "render/camera.h"
#include "render/draw_list.h"

struct GLFWwindow;
struct ImFont;

namespace polyroll::app {

class Window {
public:
    // nullptr when no window can be opened (no display); `why` says what failed.
    static std::unique_ptr<Window> open(int width_px, int height_px, bool vsync, std::string& why);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    bool should_close() const;
    // Polls events, rebuilds the fonts if the scale changed, starts an ImGui frame.
    void begin_frame();
    // Renders ImGui's draw data over the frame, where outside `scene` (framebuffer pixels) the frame
    // holds `panel_background` alone; the windows that did not change since the last frame come from a
    // copy (panel_cache.h).
    // `scene_changed`: the scene was drawn only there (the rest of it is the last frame's), so only
    // there, and where the panels draw over the scene, is it shown again; none: the whole scene.
    void render_ui(render::Rgba panel_background, const render::PxRect& scene,
                   const std::vector<render::ClipRect>* scene_changed = nullptr);
    // Shows the frame: swaps, or where the window shows parts of its back buffer (keeps_panels()),
    // copies the scene and what the panels changed.
    void swap();
    // True when the back buffer keeps the panels' pixels from frame to frame (platform.h,
    // can_present_parts): the scene then draws nothing outside its area, not even the clear.
    bool keeps_panels() const { return present_parts_; }
    // True when the back buffer holds the last frame as it was shown (shown in parts, the same size):
    // the scene may then be drawn only where it changed (render/changed_regions.h).
    bool holds_last_frame() const;
    // Where the last frame's panels drew over the scene (PanelCache::drawn_in_scene).
    std::vector<render::ClipRect> panels_in_scene() const;
    // Waits until GL has drawn everything asked of it so far (the benchmark's split of a frame).
    void finish_gl() const;
    // Sleeps until an input event arrives or `timeout_s` passes: the loop calls it when nothing
    // moves (run ended, paused), so an idle window costs no CPU.
    void wait_events(double timeout_s) const;

    void framebuffer_size(int& width_px, int& height_px) const;
    // Framebuffer pixels per window coordinate (1 except on high-density displays).
    float pixel_ratio() const;

    void set_ui_scale(float scale);  // takes effect at the next begin_frame
    void set_high_contrast(bool on);
    ImFont* large_font() const { return large_; }

    // The back buffer as RGBA rows, bottom row first (call before swap()).
    std::vector<std::uint8_t> read_back_buffer(int& width_px, int& height_px) const;
    std::string gl_renderer() const;

private:
    Window() = default;
    void build_fonts();
    void apply_style();

    GLFWwindow* window_ = nullptr;
    float scale_ = 1.0f, built_scale_ = 0.0f;
    bool high_contrast_ = true, style_dirty_ = true;
    ImFont* large_ = nullptr;
    std::string font_dir_;
    std::unique_ptr<PanelCache> panels_;
    bool present_parts_ = false;  // show parts of the back buffer instead of swapping
    bool kept_ = false;           // the back buffer holds the last frame (false: new, resized, or swapped)
    bool show_all_ = true;        // the next present copies the whole frame (the window lost its pixels)
    std::vector<PanelCache::Rect> changed_;  // this frame's: the scene's pixels and what the panels copied
    int kept_w_ = 0, kept_h_ = 0;
};

}  // namespace polyroll::app
