// run() and Simulation: one scene run to its end, or stepped and read. Both start the run exactly as
// `polyroll run` does (model_registry.h), so a scene gives the same numbers through Python as through
// the command line; the GIL is released while they compute and a Ctrl-C stops them.
#include "python/py_run.h"

#include <chrono>
#include <memory>

#include <pybind11/numpy.h>

#include "python/py_interrupt.h"
#include "python/py_json.h"
#include "python/py_result.h"
#include "python/py_scene.h"
#include "sim/model_registry.h"
#include "sim/files/results_io.h"
#include "sim/run_progress.h"
#include "sim/scene/scene_json.h"
#include "sim/scene/scene_names.h"

namespace py = pybind11;

namespace polyroll::python {

namespace {

// Runs `work` without the GIL, the run's stop hook asking `watch`; a Ctrl-C raises KeyboardInterrupt.
template <class Work>
void interruptibly(Work&& work) {
    InterruptWatch watch;
    {
        const py::gil_scoped_release nogil;
        const ScopedRunStop stop([&watch] { return watch.interrupted(); });
        try {
            work(watch);
        } catch (const RunStopped&) {
            watch.interrupted_now();  // the hook said so: the signal is pending
        }
    }
    watch.raise_if_interrupted();
}

// A run stepped from Python: a notebook's or a control loop's view of it.
class Simulation {
public:
    // The wall time counts from here, as run_scene's does: building, pouring and settling included.
    explicit Simulation(const Scene& scene) : start_(std::chrono::steady_clock::now()) {
        interruptibly([&](InterruptWatch&) { run_ = start_run(scene); });
        if (!run_) throw std::runtime_error("the run could not be started");
    }

    // Up to n tracker steps; whether the run goes on.
    bool step(long n) {
        bool going = !run_->finished();
        interruptibly([&](InterruptWatch& watch) {
            for (long i = 0; i < n && going; ++i) {
                going = run_->step();
                if (watch.interrupted()) break;
            }
        });
        return going;
    }

    RunResult run_to_end() {
        interruptibly([&](InterruptWatch&) { run_->run_to_end(); });
        return result();
    }

    RunResult result() const {
        RunResult r = run_->result();
        r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        return r;
    }

    const ModelRun& run() const { return *run_; }

private:
    std::unique_ptr<ModelRun> run_;
    std::chrono::steady_clock::time_point start_;
};

py::dict shell_state(const Simulation& s) {
    const ShellNow shell = s.run().shell_now();  // no grains copied
    py::dict d;
    d["x_m"] = shell.centre_m.x;  // the shell's centre in the ramp frame: x down the slope,
    d["y_m"] = shell.centre_m.y;  // y along its normal, the surface at y = 0
    d["angle_rad"] = shell.angle_rad;
    d["position_m"] = shell.now.position_m;  // the tracker's: lid centre from its release
    d["speed_m_s"] = shell.now.speed_m_s;
    d["rotation_deg"] = shell.now.angle_deg;
    d["impacts"] = shell.impacts;
    return d;
}

py::dict grain_state(const Simulation& s) {
    const RunSnapshot snap = s.run().snapshot();
    const auto n = static_cast<py::ssize_t>(snap.grains.size());
    py::array_t<double> x(n), y(n), radius(n), speed(n);
    auto xv = x.mutable_unchecked<1>(), yv = y.mutable_unchecked<1>(), rv = radius.mutable_unchecked<1>(),
         sv = speed.mutable_unchecked<1>();
    for (py::ssize_t i = 0; i < n; ++i) {
        const GrainState& g = snap.grains[static_cast<std::size_t>(i)];
        xv(i) = g.position_m.x;
        yv(i) = g.position_m.y;
        rv(i) = g.radius_m;
        sv(i) = g.speed_m_s;
    }
    py::dict d;
    d["x_m"] = x;
    d["y_m"] = y;
    d["radius_m"] = radius;
    d["speed_m_s"] = speed;
    return d;
}

py::dict energies(const Simulation& s) {
    const TrajectorySample now = s.run().shell_now().now;  // no grains copied
    py::dict d;
    d["kinetic_J"] = now.kinetic_J;
    d["potential_J"] = now.potential_J;
    d["dissipated_J"] = now.dissipated_J;
    return d;
}

}  // namespace

void bind_run(py::module_& m) {
    m.def(
        "resolve",
        [](py::handle source, const py::dict& keywords, const py::dict& sets, const std::string& sets_name,
           const py::object& preset, const py::object& lane) {
            std::vector<SceneLayer> layers;
            if (!preset.is_none()) layers.push_back(preset_lane_layer(preset.cast<std::string>(), lane));
            for (SceneLayer& l : scene_layers(source, keywords, sets, sets_name)) layers.push_back(std::move(l));
            return from_json(scene_to_json(resolve_scene(layers)));
        },
        py::arg("source"), py::arg("keywords"), py::arg("sets"), py::arg("sets_name") = "fields",
        py::arg("preset") = py::none(), py::arg("lane") = py::none(),
        "the resolved scene document (a dict) of a window preset's lane (preset, lane), a scene file or dict, "
        "scene keywords and FIELD: VALUE sets (named sets_name in messages)");
    m.def("window_presets", &window_preset_table, "the window's presets: name, description, lanes (scene documents)");
    m.def("scene_keywords", &keyword_table, "every scene keyword: its field, flag, type and help");
    m.def("field_types", &field_types, "every scene field's type, by its path");
    m.def(
        "run",
        [](const py::dict& scene_doc) {
            const Scene scene = resolve(scene_doc, py::dict(), py::dict());
            RunResult r;
            interruptibly([&](InterruptWatch&) { r = run_scene(scene); });
            return r;
        },
        py::arg("scene"), "runs a resolved scene document to its end (as polyroll run)");
    py::class_<Simulation>(m, "Simulation")
        .def(py::init([](const py::dict& scene_doc) {
                 return std::make_unique<Simulation>(resolve(scene_doc, py::dict(), py::dict()));
             }),
             py::arg("scene"))
        .def("step", &Simulation::step, py::arg("n") = 1)
        .def("run_to_end", &Simulation::run_to_end)
        .def("result", &Simulation::result)
        .def_property_readonly("finished", [](const Simulation& s) { return s.run().finished(); })
        .def_property_readonly("steps", [](const Simulation& s) { return s.run().steps(); })
        .def_property_readonly("time_s", [](const Simulation& s) { return s.run().time_s(); })
        .def_property_readonly("step_s", [](const Simulation& s) { return s.run().step_s(); })
        .def_property_readonly("behaviour", [](const Simulation& s) { return to_string(s.run().measured().behaviour); })
        .def_property_readonly("grain_count", [](const Simulation& s) { return s.run().grains(); })
        .def("shell", &shell_state)
        .def("grains", &grain_state)
        .def("energies", &energies)
        .def("measured", [](const Simulation& s) { return from_json(summary_json(s.result())); },
             "the summary of the run so far (its behaviour 'running' until it has ended)");
}

}  // namespace polyroll::python
