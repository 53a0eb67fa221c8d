// One frame's draw list: see frame_builder.h.
#include "render/frame_builder.h"

#include "render/close_up.h"
#include "render/overlay.h"
#include "render/world_draw.h"

namespace polyroll::render {

namespace {

WorldStyle frame_world_style(const FrameOptions& o, const FrameLayout& L, PxRect visible) {
    return world_style(L.unit, visible, o.grain_colouring, o.colour_speed_max_m_s);
}

// The close-up in the layout's inset.
void draw_inset(const Snapshot& s, const FrameOptions& o, const FrameLayout& L, const FontAtlas& font,
                const Camera& main_cam, DrawList& dl) {
    const CloseUpStyle style = close_up_style(*L.inset, L.unit);
    draw_close_up(s, main_cam, style, frame_world_style(o, L, style.rect), font, dl);
}

}  // namespace

Camera main_camera(const Snapshot& s, const FrameOptions& o, const FrameLayout& L) {
    const double R = outer_radius_m(s);
    // Following: the shell in the middle of the frame below the overlay, zoomed by the frame's height.
    if (o.follow) return follow_framing(s.shell_centre_m, s.ramp_angle_deg, R, L.world, o.height_px);
    return whole_ramp_camera(s.ramp_length_m, s.ramp_angle_deg, 2.2 * R, L.world);
}

DrawList build_frame(const Snapshot& s, const FrameOptions& o, const FontAtlas& font) {
    const FrameLayout L = frame_layout(o);
    DrawList dl;
    dl.width_px = o.width_px;
    dl.height_px = o.height_px;
    dl.background = palette::background;
    dl.atlas = &font;
    const Camera cam = main_camera(s, o, L);
    const PxRect full{0.0f, 0.0f, static_cast<float>(o.width_px), static_cast<float>(o.height_px)};
    draw_world(s, cam, frame_world_style(o, L, full), font, dl.new_layer());
    if (L.inset) draw_inset(s, o, L, font, cam, dl);
    Layer& overlay = dl.new_layer();
    draw_panel(s, o, L, font, overlay);
    draw_plot(s, o, L, font, overlay);
    draw_outcome(o, L, font, overlay);
    return dl;
}

}  // namespace polyroll::render
