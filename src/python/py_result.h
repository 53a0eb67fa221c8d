// A run's result as Python sees it: the summary as a dict (summary.json's), the trajectory and the
// impacts as columns of numpy arrays named as trajectory.csv's and impacts.csv's columns (NaN where
// the file has a blank), and the same three files written on request.
#pragma once

#include <pybind11/pybind11.h>

#include "sim/run_result.h"

namespace polyroll::python {

pybind11::dict trajectory_columns(const Measurements& m);
pybind11::dict impact_columns(const Measurements& m);

// The class _polyroll.RunResult.
void bind_result(pybind11::module_& m);

}  // namespace polyroll::python
