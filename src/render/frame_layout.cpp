// Frame layout from the frame size: see frame_layout.h.
#include "render/frame_layout.h"

#include <algorithm>

namespace polyroll::render {

FrameLayout frame_layout(const FrameOptions& o) {
    const float w = static_cast<float>(o.width_px), h = static_cast<float>(o.height_px);
    FrameLayout L;
    L.unit = std::min(w / 1280.0f, h / 720.0f);
    const float u = L.unit;
    L.margin = 16.0f * u;
    L.stroke = stroke_px(u);
    L.title = {FontFace::bold, font_px(24, u)};
    L.label = label_font(u);
    L.value = {FontFace::bold, font_px(32, u)};
    L.small = scale_font(u);

    const float panel_h = (o.grain_colouring == GrainColouring::speed ? 172.0f : 136.0f) * u;
    L.panel = {L.margin, L.margin, 600.0f * u, panel_h};  // widened to fit its text
    L.plot = {w - L.margin - 420.0f * u, L.margin, 420.0f * u, 200.0f * u};
    const float top = std::max(L.panel.y + L.panel.height, L.plot.y + L.plot.height) + 2.0f * L.margin;
    // Below the ramp: its body and the scale's labels.
    const float below = kRampBelowDesignPx * u;
    L.world = {2.0f * L.margin, top, w - 4.0f * L.margin, std::max(1.0f, h - top - L.margin - below)};
    if (!o.follow) L.inset = PxRect{L.margin, h - L.margin - 0.42f * h, 0.30f * w, 0.42f * h};
    return L;
}

std::vector<FontSpec> frame_fonts(const FrameOptions& o) {
    const FrameLayout L = frame_layout(o);
    return {L.title, L.label, L.value, L.small};
}

}  // namespace polyroll::render
