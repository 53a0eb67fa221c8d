// A run's result as Python sees it: the summary as a dict (summary.json's), the trajectory and the
// impacts as numpy record arrays with trajectory.csv's and impacts.csv's columns, both from the one
// declaration of those columns (sim/files/result_columns.h; NaN where the file has a blank), and the
// same three files written on request.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "sim/run_result.h"

namespace polyroll::python {

pybind11::array trajectory_records(const Measurements& m);
pybind11::array impact_records(const Measurements& m);

// The class _polyroll.RunResult.
void bind_result(pybind11::module_& m);

}  // namespace polyroll::python
