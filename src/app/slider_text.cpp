// A slider's value beside its knob: see slider_text.h.
#include "app/slider_text.h"

#include <algorithm>

namespace polyroll::app {

namespace {
// ImGui 1.86 (imgui_widgets.cpp, SliderBehaviorT) keeps the knob this far inside the frame.
constexpr float kGrabPaddingPx = 2.0f;
}  // namespace

KnobSpan slider_knob(float frame_min_x, float frame_max_x, double fraction, float grab_min_px, int integer_values) {
    const float slider_w = std::max(0.0f, frame_max_x - frame_min_x - 2.0f * kGrabPaddingPx);
    float knob_w = std::min(grab_min_px, slider_w);
    if (integer_values > 0) knob_w = std::max(slider_w / static_cast<float>(integer_values), knob_w);
    const float t = static_cast<float>(std::clamp(fraction, 0.0, 1.0));
    const float left = frame_min_x + kGrabPaddingPx + t * (slider_w - knob_w);
    return {left, left + knob_w};
}

float slider_value_x(float frame_min_x, float frame_max_x, KnobSpan knob, float text_w_px, float gap_px) {
    const float right_room = frame_max_x - knob.max_x;
    const float left_room = knob.min_x - frame_min_x;
    const float needed = text_w_px + 2.0f * gap_px;
    if (right_room >= needed) return knob.max_x + gap_px;
    if (left_room >= needed) return knob.min_x - gap_px - text_w_px;
    return right_room >= left_room ? knob.max_x + gap_px : knob.min_x - gap_px - text_w_px;
}

}  // namespace polyroll::app
