// sweep(): a grid of scenes in the command line's vocabulary, planned into a sweep folder and run in
// parallel exactly as `polyroll sweep --out` does (sweep/grid_request.h, sweep/sweep_runner.h):
// the same request resumes or extends the folder, and a Ctrl-C stops it after the runs in flight.
#include "python/py_sweep.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <thread>

#include <fmt/core.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "python/py_interrupt.h"
#include "python/py_json.h"
#include "python/py_scene.h"
#include "sim/errors.h"
#include "sim/scene/scene_json.h"
#include "sweep/grid_request.h"
#include "sweep/sweep_runner.h"

namespace py = pybind11;

namespace polyroll::python {

namespace {

namespace fs = std::filesystem;

sweep::GridRequest request_of(py::handle base, const py::dict& axes, const py::dict& sets, const std::string& seed_list,
                              int seeds, bool large) {
    sweep::GridRequest r;
    if (py::isinstance<py::dict>(base)) {
        r.base = to_json(base, "scene");
        r.base_origin = "the scene dict";
    } else if (!base.is_none()) {
        const std::string path = py::str(py::module_::import("os").attr("fspath")(base)).cast<std::string>();
        r.base = read_scene_file(path).doc;
        r.base_origin = path;
    }
    // The swept keywords: the scene flags polyroll sweep takes a grid for.
    const std::vector<const SceneField*> swept_fields = sweep::axis_fields();
    std::string swept;
    for (const SceneField* f : swept_fields) swept += (swept.empty() ? "" : ", ") + keyword_of_flag(f->flag);
    for (const auto& [key, text] : axes) {
        const std::string keyword = key.cast<std::string>(), flag = flag_of_keyword(keyword);
        if (std::none_of(swept_fields.begin(), swept_fields.end(), [&flag](const SceneField* f) { return f->flag == flag; }))
            throw py::type_error(fmt::format("unexpected keyword argument '{}' (allowed: the swept keywords {}; any "
                                             "field with fields={{\"FIELD\": VALUES}})",
                                             keyword, swept));
        r.axis_text[flag] = text.cast<std::string>();
    }
    for (const auto& [field, text] : sets) r.sets.push_back(field.cast<std::string>() + "=" + text.cast<std::string>());
    r.seed_list = seed_list;
    r.seeds = seeds;
    r.large = large;
    return r;
}

}  // namespace

void bind_sweep(py::module_& m) {
    m.def(
        "sweep",
        [](const fs::path& out, py::handle base, const py::dict& axes, const py::dict& sets, const std::string& seed_list,
           int seeds, int jobs, bool trajectories, bool retry_failed, bool large, bool quiet) {
            const sweep::GridRequest request = request_of(base, axes, sets, seed_list, seeds, large);
            std::vector<std::string> notes;
            sweep::SweepPlan plan = sweep::make_request_plan(request, notes);
            const sweep::GridCheck check = sweep::check_grid(plan);
            sweep::refuse_unrunnable(plan, check, jobs, large);
            sweep::open_sweep_folder(out, "out=", plan, notes);

            sweep::SweepOptions o;
            o.dir = out;
            o.jobs = jobs;
            o.trajectories = trajectories;
            o.retry_failed = retry_failed;
            o.quiet = quiet;
            std::atomic<bool> stop{false};
            sweep::SweepReport report;
            std::exception_ptr failure;
            InterruptWatch watch;
            {
                // The pool runs on its own threads; this one waits and looks for a Ctrl-C, which ends
                // the session after the runs in flight (the same call resumes it).
                const py::gil_scoped_release nogil;
                std::atomic<bool> done{false};
                std::thread runner([&] {
                    try {
                        report = sweep::run_sweep(plan, o, &stop);
                    } catch (...) {
                        failure = std::current_exception();
                    }
                    done = true;
                });
                while (!done) {
                    std::this_thread::sleep_for(std::chrono::milliseconds(100));
                    if (!stop && watch.interrupted_now()) stop = true;
                }
                runner.join();
            }
            if (failure) std::rethrow_exception(failure);
            watch.raise_if_interrupted();
            py::dict d;
            d["planned"] = report.planned;
            d["already"] = report.already;
            d["ran"] = report.ran;
            d["failed"] = report.failed;
            d["first_failure"] = report.first_failure;
            d["wall_time_s"] = report.wall_time_s;
            d["table"] = report.table;
            d["notes"] = notes;
            return d;
        },
        py::arg("out"), py::arg("scene"), py::arg("axes"), py::arg("sets"), py::arg("seed_list"), py::arg("seeds"),
        py::arg("jobs"), py::arg("trajectories"), py::arg("retry_failed"), py::arg("large"), py::arg("quiet"),
        "plans the grid into the folder `out` (or resumes or extends the sweep there) and runs what is left");
}

}  // namespace polyroll::python
