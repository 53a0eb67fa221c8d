// The compiled half of `import polyroll` (_polyroll): scenes, runs, steppable simulations and sweeps
// over the same core as the command line. polyroll/__init__.py is the half users call.
#include <pybind11/pybind11.h>

#include "python/py_result.h"
#include "python/py_run.h"
#include "python/py_sweep.h"
#include "sim/build_info.h"
#include "sim/errors.h"

namespace py = pybind11;

PYBIND11_MODULE(_polyroll, m) {
    m.doc() = "polyroll's simulation core (use the polyroll package, not this module)";
    // Bad input is the command line's one line, as ValueError. The translator's type is pybind11's
    // void (*)(std::exception_ptr): the pointer is taken by value.
    py::register_exception_translator([](std::exception_ptr p) {  // NOLINT(performance-unnecessary-value-param)
        try {
            if (p) std::rethrow_exception(p);
        } catch (const polyroll::InputError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        }
    });
    m.attr("version") = polyroll::version_text("polyroll");
    polyroll::python::bind_result(m);
    polyroll::python::bind_run(m);
    polyroll::python::bind_sweep(m);
}
