// A headless GL 3.3 core context from OSMesa (Mesa's llvmpipe on the CPU): no display, no X server,
// no GPU. Its framebuffer is plain memory we own, read back after glFinish. Only executables that
// link libOSMesa (and not libGL: both export the GL API: docs/design.md) may use this.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace polyroll::render {

class OffscreenContext {
public:
    // Creates the context and makes it current on this thread. Throws std::runtime_error.
    OffscreenContext(int width, int height);
    ~OffscreenContext();
    OffscreenContext(const OffscreenContext&) = delete;
    OffscreenContext& operator=(const OffscreenContext&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    std::string renderer() const;  // GL_RENDERER and GL_VERSION, for reports

    // Waits for drawing to finish and copies the buffer as it is: RGBA, bottom row first (GL's
    // order), width x height x 4 bytes. The PNG encoder drops alpha and flips rows on its own thread.
    void read_rgba_bottom_up(std::uint8_t* rgba) const;

private:
    int width_, height_;
    void* context_ = nullptr;
    std::vector<std::uint8_t> buffer_;  // RGBA, bottom row first
};

}  // namespace polyroll::render
