// The scene's look at a design pixel: see view_style.h.
#include "render/view_style.h"

#include <algorithm>
#include <cmath>

namespace polyroll::render {

int font_px(float design_px, float unit) { return std::max(6, static_cast<int>(std::lround(design_px * unit))); }

float stroke_px(float unit) { return std::max(1.0f, 2.5f * unit); }

FontSpec scale_font(float unit) { return {FontFace::regular, font_px(17, unit)}; }
FontSpec label_font(float unit) { return {FontFace::regular, font_px(19, unit)}; }

WorldStyle world_style(float unit, PxRect visible, GrainColouring how, double colour_speed_max_m_s) {
    WorldStyle st;
    st.unit = unit;
    st.stroke = stroke_px(unit);
    st.scale_font = scale_font(unit);
    st.visible = visible;
    st.grain_colouring = how;
    st.colour_speed_max_m_s = colour_speed_max_m_s;
    return st;
}

}  // namespace polyroll::render
