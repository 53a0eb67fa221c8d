// run(), resolve() and the Simulation class of the module (py_run.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace polyroll::python {

void bind_run(pybind11::module_& m);

}  // namespace polyroll::python
