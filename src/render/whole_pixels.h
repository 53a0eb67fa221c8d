// Float pixel coordinates to whole pixels, for the per-primitive sums done thousands of times a frame
// (changed_regions.cpp, disc_splat.cpp): std::floor and std::ceil compile to library calls for the
// baseline x86-64 (no SSE4.1 rounding), which were a few percent of the window's UI thread.
#pragma once

namespace polyroll::render {

// For |v| well inside an int's range (callers clamp far-off coordinates first).
inline int floor_px(float v) {
    const int i = static_cast<int>(v);  // rounds toward zero
    return static_cast<float>(i) > v ? i - 1 : i;
}
inline int ceil_px(float v) {
    const int i = static_cast<int>(v);
    return static_cast<float>(i) < v ? i + 1 : i;
}

}  // namespace polyroll::render
