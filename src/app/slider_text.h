// Where a slider's value is written: beside its knob, never under it, so it stays readable. ImGui 1.86
// centres the value in the frame, so the knob covers it whenever the value sits mid-range; the
// sandbox hides that text and draws the value at the x this returns. GL-free, so the tests check it.
#pragma once

namespace polyroll::app {

// A slider knob's horizontal extent in window pixels, as ImGui 1.86's SliderBehavior places it.
struct KnobSpan {
    float min_x = 0, max_x = 0;
};

// The knob of a slider whose frame spans [frame_min_x, frame_max_x], at `fraction` (0 to 1, clamped)
// of its range. `knob_w_px` is the knob's width: ImGui's GrabMinSize, or for an integer slider
// with few values the frame's width shared among them (integer_values > 0).
KnobSpan slider_knob(float frame_min_x, float frame_max_x, double fraction, float grab_min_px, int integer_values = 0);

// The left x of a value text `text_w_px` wide: right of the knob when it fits inside the frame,
// else left of it, else (a frame too narrow for either) on the side with more room. `gap_px` is
// kept between the text and the knob and the frame's edges.
float slider_value_x(float frame_min_x, float frame_max_x, KnobSpan knob, float text_w_px, float gap_px);

}  // namespace polyroll::app
