// sweep() of the module (py_sweep.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace polyroll::python {

void bind_sweep(pybind11::module_& m);

}  // namespace polyroll::python
