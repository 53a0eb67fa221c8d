// ImGui's panels drawn from a copy kept in a texture, redrawn only where a window's draw list changed
// since the last frame. A software GL (llvmpipe under Xvfb, SwiftShader in a browser) pays for each
// triangle it sets up: the panels' 6,000-7,000 triangles took 7 ms a frame at 1280x800 (the window's
// --bench on hexagon-large-bb), while between touches most of them (the control panel's) do not
// change; the status band does, and the readouts and plots when they move, and only they are redrawn.
//
// The panels tile the window with the scene and draw no background of their own (sandbox_ui.cpp):
// the copy is cleared to their colour, so outside the scene it holds the pixels drawing the lists over
// the cleared frame gives (llvmpipe rounds a blend into the copy's format and the window's apart by one
// level on a few dozen edge pixels of a frame), and is copied there as it is (a blit, no blending). What
// the lists draw inside the scene (a border's edge, an open combo or tooltip) is drawn over it
// directly, as before. Measured (--bench, hexagon-large-bb, 1280x800, llvmpipe, the 3D runs paused):
// the panels' GL 7.0 ms a frame drawn directly, 4.3 ms from the copy, of which the copy's blit is 3.3.
// Where the window shows its frame by copying parts of a back buffer it never swaps (Window::swap),
// `kept` says the framebuffer still holds what the last render left, and only the changed
// rectangles are copied: the panels' GL fell from about 6 to 1.8 ms (docs/sandbox.md).
#pragma once

#include <cstdint>
#include <vector>

#include "render/colour.h"
#include "render/camera.h"

struct ImDrawData;
struct ImDrawList;

namespace polyroll::app {

class PanelCache {
public:
    PanelCache();  // needs a current GL context (OpenGL 3.3 core or WebGL 2)
    ~PanelCache();
    PanelCache(const PanelCache&) = delete;
    PanelCache& operator=(const PanelCache&) = delete;

    // A rectangle in framebuffer pixels, rows from the top; empty when x1 <= x0 or y1 <= y0.
    struct Rect {
        int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        bool empty() const { return x1 <= x0 || y1 <= y0; }
    };

    // Draws `data` over the bound default framebuffer, as ImGui_ImplOpenGL3_RenderDrawData would,
    // where the frame outside `scene` (framebuffer pixels) is `background` and nothing else.
    // `kept`: the framebuffer still holds, outside the scene, what the last render left there (a back
    // buffer shown by copying parts of it, never swapped: Window::swap); then only what changed is
    // copied. Returns the rectangles copied outside the scene.
    std::vector<Rect> render(ImDrawData* data, render::Rgba background, const render::PxRect& scene, bool kept);
    // Redraws everything at the next render (the font texture was rebuilt).
    void invalidate() { lists_.clear(); }
    // Where the last render drew lists over the scene (a border's edge, an open combo): the scene's
    // pixels there were blended over, so a scene drawn only where it changed draws these again too.
    const std::vector<Rect>& drawn_in_scene() const { return drawn_in_scene_; }

private:
    struct ListState {
        const ImDrawList* list = nullptr;  // ImGui keeps a window's list from frame to frame
        std::uint64_t hash = 0;            // of its vertices, indices and commands
        Rect bounds;                       // what it can touch
    };
    void resize(int width_px, int height_px);
    // Draws the lists that reach into `clip` into the bound framebuffer, each command clipped to it.
    void draw_clipped(ImDrawData* data, const std::vector<ListState>& now, const Rect& clip) const;

    std::vector<ListState> lists_;  // the last frame's
    Rect inside_;                   // the last frame's scene pixels
    std::vector<Rect> drawn_in_scene_;
    render::Rgba background_{};
    int width_px_ = 0, height_px_ = 0;
    unsigned texture_ = 0, framebuffer_ = 0;
};

}  // namespace polyroll::app
