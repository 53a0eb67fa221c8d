// A run's result for Python: see py_result.h.
#include "python/py_result.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl/filesystem.h>

#include "python/py_json.h"
#include "sim/files/atomic_file.h"
#include "sim/files/results_io.h"

namespace py = pybind11;

namespace polyroll::python {

namespace {

constexpr double kBlank = std::numeric_limits<double>::quiet_NaN();

template <class Row, class Get>
py::array_t<double> column(const std::vector<Row>& rows, Get get) {
    py::array_t<double> out(static_cast<py::ssize_t>(rows.size()));
    auto view = out.mutable_unchecked<1>();
    for (std::size_t i = 0; i < rows.size(); ++i) view(static_cast<py::ssize_t>(i)) = get(rows[i]);
    return out;
}

double or_blank(const std::optional<double>& v) { return v ? *v : kBlank; }

}  // namespace

py::dict trajectory_columns(const Measurements& m) {
    const auto& t = m.trajectory;
    py::dict c;
    c["time_s"] = column(t, [](const TrajectorySample& s) { return s.time_s; });
    c["position_m"] = column(t, [](const TrajectorySample& s) { return s.position_m; });
    c["speed_m_s"] = column(t, [](const TrajectorySample& s) { return s.speed_m_s; });
    c["angle_deg"] = column(t, [](const TrajectorySample& s) { return s.angle_deg; });
    c["kinetic_J"] = column(t, [](const TrajectorySample& s) { return s.kinetic_J; });
    c["potential_J"] = column(t, [](const TrajectorySample& s) { return s.potential_J; });
    c["dissipated_J"] = column(t, [](const TrajectorySample& s) { return s.dissipated_J; });
    c["fill_ahead_m"] = column(t, [](const TrajectorySample& s) { return or_blank(s.fill_ahead_m); });
    c["fill_up_m"] = column(t, [](const TrajectorySample& s) { return or_blank(s.fill_up_m); });
    return c;
}

py::dict impact_columns(const Measurements& m) {
    const auto& f = m.impacts;
    // As impacts.csv: the delayed reading only where there is one and an energy before to divide by.
    const auto delayed = [](const FaceImpact& i) {
        return i.kinetic_delayed_J && i.kinetic_before_J > 0.0 ? std::optional<double>(*i.kinetic_delayed_J) : std::nullopt;
    };
    py::dict c;
    c["impact"] = column(f, [](const FaceImpact& i) { return static_cast<double>(i.index); });
    c["time_s"] = column(f, [](const FaceImpact& i) { return i.time_s; });
    c["position_m"] = column(f, [](const FaceImpact& i) { return i.position_m; });
    c["kinetic_before_J"] = column(f, [](const FaceImpact& i) { return i.kinetic_before_J; });
    c["kinetic_after_J"] = column(f, [](const FaceImpact& i) { return i.kinetic_after_J; });
    c["ratio"] = column(f, [](const FaceImpact& i) { return i.ratio(); });
    c["kinetic_3ms_after_J"] = column(f, [&delayed](const FaceImpact& i) { return or_blank(delayed(i)); });
    c["ratio_3ms"] = column(f, [&delayed](const FaceImpact& i) {
        const std::optional<double> d = delayed(i);
        return d ? *d / i.kinetic_before_J : kBlank;
    });
    return c;
}

void bind_result(py::module_& m) {
    py::class_<RunResult>(m, "RunResult", "What one run gave back (the C++ RunResult).")
        .def("summary", [](const RunResult& r) { return from_json(summary_json(r)); },
             "summary.json's document as a dict")
        .def("trajectory_columns", [](const RunResult& r) { return trajectory_columns(r.measured); })
        .def("impact_columns", [](const RunResult& r) { return impact_columns(r.measured); })
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
