// Where a window frame's time goes, for --bench: the parts the UI thread runs one after the other,
// and the physics worker's step beside them. Plain numbers; the loop measures them, this prints them.
#pragma once

namespace polyroll::app {

struct FrameSplit {
    double panels_s = 0.0;       // ImGui's frame: events, the control panel, readouts and plots, status
    double snapshots_s = 0.0;    // copying the lanes' state for the picture (the worker is idle)
    double scene_list_s = 0.0;   // the scene's draw list (no GL)
    double scene_gl_s = 0.0;     // the draw list drawn, until GL has finished it
    double panels_gl_s = 0.0;    // ImGui's draw data drawn, until GL has finished it
    double swap_s = 0.0;         // presenting the frame
    double physics_wait_s = 0.0; // the UI thread waiting for the worker's step after its own work
    double physics_s = 0.0;      // the worker's step (the engine, the tracker, the budget), beside the above

    FrameSplit& operator+=(const FrameSplit& o) {
        panels_s += o.panels_s;
        snapshots_s += o.snapshots_s;
        scene_list_s += o.scene_list_s;
        scene_gl_s += o.scene_gl_s;
        panels_gl_s += o.panels_gl_s;
        swap_s += o.swap_s;
        physics_wait_s += o.physics_wait_s;
        physics_s += o.physics_s;
        return *this;
    }
    // What the UI thread spends besides waiting for the physics.
    double ui_thread_s() const { return panels_s + snapshots_s + scene_list_s + scene_gl_s + panels_gl_s + swap_s; }
};

// Prints the split of `sum` over `frames` frames as --bench's indented lines, in ms per frame.
void print_split(const FrameSplit& sum, double frames);

}  // namespace polyroll::app
