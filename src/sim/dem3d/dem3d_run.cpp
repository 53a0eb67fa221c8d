// The 3D reference's run: see dem3d_run.h.
#include "sim/dem3d/dem3d_run.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "sim/dem3d/dem3d_input.h"
#include "sim/dem3d/yade_process.h"
#include "sim/geometry/shell_outline.h"
#include "sim/geometry/shell_properties.h"
#include "sim/geometry/vertex_rounding.h"
#include "sim/reveal_steps.h"

namespace polyroll::dem3d {

namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) throw std::runtime_error(fmt::format("the 3D reference wrote no {}", p.filename().string()));
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The folder the script works in: $POLYROLL_DEM3D_WORKDIR (kept, for looking into a run), else a new
// temporary folder removed when the run has been read.
class WorkDir {
public:
    WorkDir() {
        if (const char* env = std::getenv("POLYROLL_DEM3D_WORKDIR"); env && *env) {
            path_ = env;
            fs::create_directories(path_);
            return;
        }
        remove_orphans();
        std::string pattern = (fs::temp_directory_path() / fmt::format("polyroll-dem3d-{}-XXXXXX", ::getpid())).string();
        if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot make a temporary folder for Yade");
        path_ = pattern;
        remove_ = true;
    }
    ~WorkDir() {
        std::error_code ec;
        if (remove_) fs::remove_all(path_, ec);
    }
    WorkDir(const WorkDir&) = delete;
    WorkDir& operator=(const WorkDir&) = delete;
    const fs::path& path() const { return path_; }

private:
    // A polyroll stopped by a signal (Ctrl-C) leaves its folder behind: Yade dies with it, the
    // destructor never runs. The folder names its process: one whose process has gone is removed.
    static void remove_orphans() {
        std::error_code ec;
        for (const auto& e : fs::directory_iterator(fs::temp_directory_path(), ec)) {
            const std::string name = e.path().filename().string();
            const std::string prefix = "polyroll-dem3d-";
            if (name.rfind(prefix, 0) != 0) continue;
            const long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
            if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) fs::remove_all(e.path(), ec);
        }
    }

    fs::path path_;
    bool remove_ = false;
};

// A 3D shell touches the ramp with the spheres along its edges, set in from each outer vertex until
// they touch both faces (the rounded corner of vertex_rounding.h): when they touch, the sharp vertex
// stands vertex_rounding_lift_max_m above the surface, less the spheres' soft overlap. A vertex
// within that and this margin counts as touching, as the tracker's tolerance does for Box2D's skin.
constexpr double kContactMargin_m = 0.00025;

}  // namespace

std::vector<GrainFrame> parse_grains_csv(const std::string& text, double depth_m) {
    std::istringstream in(text);
    std::string line;
    if (!std::getline(in, line) || line != "time_s,grain,x_m,y_m,z_m,radius_m")
        throw std::runtime_error("grains.csv: the first line is not the header 'time_s,grain,x_m,y_m,z_m,radius_m'");
    std::vector<GrainFrame> frames;
    int line_no = 1;
    while (std::getline(in, line)) {
        ++line_no;
        if (line.empty()) continue;
        double t = 0.0, x = 0.0, y = 0.0, z = 0.0, r = 0.0;
        int id = 0;
        if (std::sscanf(line.c_str(), "%lf,%d,%lf,%lf,%lf,%lf", &t, &id, &x, &y, &z, &r) != 6)
            throw std::runtime_error(fmt::format("grains.csv line {}: not six numbers", line_no));
        if (frames.empty() || frames.back().time_s != t) frames.push_back({t, {}});
        GrainState g;
        g.position_m = {x, y};
        g.radius_m = r;
        // z runs from -depth/2 (the near lid) to +depth/2.
        g.depth = depth_m > 0.0 ? std::clamp(z / depth_m + 0.5, 0.0, 1.0) : 0.5;
        frames.back().grains.push_back(g);
    }
    return frames;
}

Dem3dOutput read_output(const Scene& scene, const fs::path& dir) {
    Dem3dOutput out;
    out.rows = parse_states_csv(read_text(dir / "states.csv"));
    if (out.rows.empty()) throw std::runtime_error("the 3D reference wrote no state (states.csv has no rows)");
    const auto setup = nlohmann::json::parse(read_text(dir / "setup.json"));
    if (fs::exists(dir / "grains.csv")) out.frames = parse_grains_csv(read_text(dir / "grains.csv"), scene.shell.depth_m);

    RunResult& r = out.result;
    r.scene = scene;
    r.shell = shell_properties(scene.shell);
    r.grains = setup.value("grains", 0);
    r.fill_mass_kg = setup.value("fill_mass_kg", 0.0);
    r.settle_time_s = setup.value("settle_time_s", 0.0);
    r.settled = setup.value("settled", true);
    r.balance_correction_deg = setup.value("balance_correction_deg", 0.0);
    // summary.json's "dem3d_engine" block (RunResult::model_blocks); Dem3dRun sets the threads it ran.
    nlohmann::ordered_json engine;
    engine["yade_version"] = setup.value("yade_version", "");
    engine["time_step_s"] = setup.value("time_step_s", 0.0);
    engine["cpu_time_s"] = setup.value("cpu_time_s", 0.0);
    engine["threads"] = 1;
    if (setup.contains("channel")) {
        // How far the box moved out of its plane (across the track from where it was released; its roll
        // axis turned about the ramp's normal, down the ramp), and how often and how hard its ends
        // touched the channel's sides (one reading per tracker step).
        const auto& c = setup["channel"];
        engine["channel"] = {{"max_offset_m", c.value("max_offset_m", 0.0)},
                             {"max_yaw_deg", c.value("max_yaw_deg", 0.0)},
                             {"max_tilt_deg", c.value("max_tilt_deg", 0.0)},
                             {"steps", c.value("rows", 0L)},
                             {"steps_touching", c.value("rows_touching", 0L)},
                             {"max_side_force_N", c.value("max_side_force_N", 0.0)},
                             {"side_impulse_N_s", c.value("side_impulse_N_s", 0.0)}};
    }
    const double time_step_s = engine["time_step_s"].get<double>();
    r.model_blocks.json()["dem3d_engine"] = engine;

    TrackRules rules;
    rules.grains = r.grains;
    rules.energy_scale_J = (r.shell.mass_kg + r.fill_mass_kg) * scene.run.gravity_m_s2 * r.shell.pivot_radius_m;
    ShellParams edges = scene.shell;
    edges.vertex_radius_m = edge_sphere_radius_m(scene);
    rules.contact_tolerance_m = kContactMargin_m + vertex_rounding_lift_max_m(edges);
    r.measured = measure_states(scene, out.rows, rules);
    if (time_step_s > 0.0) r.steps = std::lround(r.measured.end_time_s / time_step_s);
    return out;
}

Dem3dRun::Dem3dRun(const Scene& scene) : scene_(scene) {
    const WorkDir dir;
    const int threads = run_script(script_input(scene, scene.run.sample_hz), dir.path());
    Dem3dOutput out = read_output(scene, dir.path());
    full_ = std::move(out.result);
    full_.model_blocks.json()["dem3d_engine"]["threads"] = threads;
    rows_ = std::move(out.rows);
    frames_ = std::move(out.frames);
    outer_ = shell_outer_polygon_m(scene.shell);
    inner_ = shell_inner_polygon_m(scene.shell);
    shown_.behaviour = Behaviour::running;
    reveal();
}

bool Dem3dRun::finished() const { return time_s() >= full_.measured.end_time_s - 1e-12; }

bool Dem3dRun::step() {
    if (finished()) return false;
    ++steps_;
    reveal();
    return !finished();
}

void Dem3dRun::run_to_end() {
    steps_ = first_step_at_end(full_.measured.end_time_s, scene_.fidelity.step_hz, steps_);
    reveal();
}

std::unique_ptr<ModelRun> Dem3dRun::replay() const {
    std::unique_ptr<Dem3dRun> again(new Dem3dRun(*this));
    again->steps_ = 0;
    again->shown_ = Measurements{};
    again->shown_.behaviour = Behaviour::running;
    again->reveal();
    return again;
}

void Dem3dRun::reveal() { reveal_up_to(shown_, full_.measured, time_s(), finished()); }

StateRow Dem3dRun::state_now() const {
    // The rows are one a tracker step, so the step count indexes them.
    const size_t i = std::min(static_cast<size_t>(std::max(0L, steps_)), rows_.size() - 1);
    return rows_[i];
}

RunSnapshot Dem3dRun::snapshot() const {
    RunSnapshot s = scene_snapshot(scene_, outer_, inner_);
    s.time_s = std::min(time_s(), full_.measured.end_time_s);
    const StateRow r = state_now();
    s.shell_centre_m = r.shell.pose.centre_m;
    s.shell_angle_rad = r.shell.pose.angle_rad;
    if (!frames_.empty()) {
        // The latest frame at or before now.
        auto it = std::upper_bound(frames_.begin(), frames_.end(), s.time_s + 1e-9,
                                   [](double t, const GrainFrame& f) { return t < f.time_s; });
        s.grains = (it == frames_.begin() ? frames_.front() : *(it - 1)).grains;
    }
    TrajectorySample now = trajectory_sample(r, rows_.front(), full_.grains > 0);
    now.time_s = s.time_s;
    set_measured(s, now, shown_);
    return s;
}

HandOver Dem3dRun::hand_over() const {
    const StateRow r = state_now();
    return counted_hand_over(steps_, r.shell, rows_.front().shell.pose, shown_, r.potential_J);
}

}  // namespace polyroll::dem3d
