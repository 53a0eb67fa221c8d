// The frame's split for --bench: see frame_split.h.
#include "app/frame_split.h"

#include <fmt/core.h>

namespace polyroll::app {

void print_split(const FrameSplit& sum, double frames) {
    if (frames <= 0.0) return;
    const auto ms = [&](double s) { return 1e3 * s / frames; };
    fmt::print("  split        ms per frame, UI thread: panels {:.2f}, snapshots {:.2f}, scene draw list {:.2f}, "
               "scene GL {:.2f}, panels GL {:.2f}, swap {:.2f} (sum {:.2f}), then waiting for the physics {:.2f}; "
               "physics worker {:.2f} beside them\n",
               ms(sum.panels_s), ms(sum.snapshots_s), ms(sum.scene_list_s), ms(sum.scene_gl_s), ms(sum.panels_gl_s),
               ms(sum.swap_s), ms(sum.ui_thread_s()), ms(sum.physics_wait_s), ms(sum.physics_s));
}

}  // namespace polyroll::app
