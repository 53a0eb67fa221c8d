// Work that runs with the GIL released and stops at a Ctrl-C: Python's own SIGINT handler only notes
// the signal, and the work asks here (every step of a run, the 3D reference's subprocess every 0.2 s,
// the sweep's waiting thread every 0.1 s) whether one has arrived. The caller then raises it
// (KeyboardInterrupt) with the GIL held.
#pragma once

#include <chrono>

namespace polyroll::python {

class InterruptWatch {
public:
    // Called without the GIL: whether a signal is pending (Python's error is then set, to be raised).
    // Looks at most every 50 ms; true from the first pending signal on.
    bool interrupted();
    // Forces a look now, whatever the time since the last.
    bool interrupted_now();
    // With the GIL held: raises the pending exception if a signal arrived.
    void raise_if_interrupted() const;

private:
    bool interrupted_ = false;
    std::chrono::steady_clock::time_point last_{};
};

}  // namespace polyroll::python
