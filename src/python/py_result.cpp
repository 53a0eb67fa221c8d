// A run's result for Python: see py_result.h.
#include "python/py_result.h"

#include <filesystem>
#include <limits>
#include <optional>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl/filesystem.h>

#include "python/py_json.h"
#include "sim/files/atomic_file.h"
#include "sim/files/result_columns.h"
#include "sim/files/results_io.h"

namespace py = pybind11;

namespace polyroll::python {

namespace {

// The declared columns (result_columns.h) as one numpy record array, a float64 field each, filled in
// place: one allocation and one pass, no per-column arrays joined afterwards. NaN where the CSV has a
// blank.
template <class Row>
py::array records(std::span<const ResultColumn<Row>> columns, const std::vector<Row>& rows) {
    py::list names, formats;
    for (const ResultColumn<Row>& c : columns) {
        names.append(std::string(c.name));
        formats.append("f8");
    }
    py::dict spec;
    spec["names"] = names;
    spec["formats"] = formats;
    py::array out(py::dtype::from_args(spec), std::vector<py::ssize_t>{static_cast<py::ssize_t>(rows.size())});
    auto* data = static_cast<double*>(out.mutable_data());
    const std::size_t width = columns.size();
    for (std::size_t i = 0; i < rows.size(); ++i)
        for (std::size_t c = 0; c < width; ++c)
            data[i * width + c] = columns[c].value(rows[i]).value_or(std::numeric_limits<double>::quiet_NaN());
    return out;
}

}  // namespace

py::array trajectory_records(const Measurements& m) { return records(trajectory_columns(), m.trajectory); }
py::array impact_records(const Measurements& m) { return records(impact_columns(), m.impacts); }

void bind_result(py::module_& m) {
    py::class_<RunResult>(m, "RunResult", "What one run gave back (the C++ RunResult).")
        .def("summary", [](const RunResult& r) { return from_json(summary_json(r)); },
             "summary.json's document as a dict")
        .def("trajectory_records", [](const RunResult& r) { return trajectory_records(r.measured); },
             "trajectory.csv's columns as one numpy record array")
        .def("impact_records", [](const RunResult& r) { return impact_records(r.measured); },
             "impacts.csv's columns as one numpy record array")
        .def(
            "save",
            [](const RunResult& r, const std::filesystem::path& dir, bool force) {
                // As `polyroll run --out`: a new or empty folder (force: any), nothing half-written.
                const std::optional<std::filesystem::path> created = prepare_output_dir(
                    dir, force, "use force=True to overwrite its files, or choose a new folder");
                try {
                    write_run_files(dir, r);
                } catch (...) {
                    std::error_code ec;
                    if (created) std::filesystem::remove_all(*created, ec);
                    throw;
                }
            },
            py::arg("dir"), py::arg("force") = false,
            "writes summary.json, trajectory.csv and impacts.csv into dir, as polyroll run --out does");
}

}  // namespace polyroll::python
