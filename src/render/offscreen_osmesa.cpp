// The OSMesa offscreen context: see offscreen_osmesa.h.
#define GL_GLEXT_PROTOTYPES 1
#include "render/offscreen_osmesa.h"

#include <GL/osmesa.h>

#include <cstring>
#include <stdexcept>

#include <fmt/core.h>

namespace polyroll::render {

OffscreenContext::OffscreenContext(int width, int height)
    : width_(width), height_(height), buffer_(static_cast<size_t>(width) * static_cast<size_t>(height) * 4) {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS, 0,
                           OSMESA_ACCUM_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx) throw std::runtime_error("OSMesa could not create a GL 3.3 core context (is libosmesa6 installed?)");
    if (!OSMesaMakeCurrent(ctx, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
        OSMesaDestroyContext(ctx);
        throw std::runtime_error(fmt::format("OSMesa could not make a {}x{} context current", width, height));
    }
    context_ = ctx;
}

OffscreenContext::~OffscreenContext() {
    if (context_) OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

std::string OffscreenContext::renderer() const {
    const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const auto* v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return fmt::format("{}, {}", r ? r : "?", v ? v : "?");
}

}  // namespace polyroll::render

namespace polyroll::render {

void OffscreenContext::read_rgba_bottom_up(std::uint8_t* rgba) const {
    glFinish();
    std::memcpy(rgba, buffer_.data(), buffer_.size());
}

}  // namespace polyroll::render
