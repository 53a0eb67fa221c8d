// Work stopped by a Ctrl-C: see py_interrupt.h.
#include "python/py_interrupt.h"

#include <pybind11/pybind11.h>

namespace py = pybind11;

namespace polyroll::python {

bool InterruptWatch::interrupted() {
    if (interrupted_) return true;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(50)) return false;
    return interrupted_now();
}

bool InterruptWatch::interrupted_now() {
    if (interrupted_) return true;
    last_ = std::chrono::steady_clock::now();
    const py::gil_scoped_acquire gil;
    // Runs Python's handlers of the signals that arrived (SIGINT's raises KeyboardInterrupt): only on
    // the main thread; elsewhere it returns 0 and the work goes on.
    if (PyErr_CheckSignals() != 0) interrupted_ = true;
    return interrupted_;
}

void InterruptWatch::raise_if_interrupted() const {
    if (interrupted_) throw py::error_already_set();
}

}  // namespace polyroll::python
