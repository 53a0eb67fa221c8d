// Running Yade: see yade_process.h.
#include "sim/dem3d/yade_process.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include <unistd.h>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "process/child_process.h"
#include "process/installed_script.h"
#include "sim/files/atomic_file.h"
#include "sim/errors.h"
#include "sim/run_cores.h"
#include "sim/run_progress.h"

namespace polyroll::dem3d {

namespace fs = std::filesystem;

namespace {

bool executable(const fs::path& p) { return ::access(p.c_str(), X_OK) == 0 && fs::is_regular_file(p); }

// The last `keep` characters of what the script said on stderr: its one-line reason comes last.
std::string tail(const std::string& s, size_t keep) { return s.size() <= keep ? s : "..." + s.substr(s.size() - keep); }

std::string last_line(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
    const size_t nl = s.rfind('\n');
    return nl == std::string::npos ? s : s.substr(nl + 1);
}

}  // namespace

std::string yade_command() {
    if (const char* env = std::getenv("POLYROLL_YADE"); env && *env) {
        if (executable(env)) return env;
        throw InputError(fmt::format("POLYROLL_YADE={}: not an executable file (unset it to use yade from the PATH)", env));
    }
    if (std::string on_path = process::find_on_path("yade"); !on_path.empty()) return on_path;
    throw InputError("--model dem3d needs Yade, which is not installed: run third_party/setup.sh (or apt-get install "
                     "yade) as root");
}

std::string script_path() {
#ifdef POLYROLL_DEM3D_SOURCE_DIR
    const char* source_dir = POLYROLL_DEM3D_SOURCE_DIR;
#else
    const char* source_dir = nullptr;
#endif
    return process::installed_script(
        {"polyroll_dem3d.py", "the 3D reference's script", "POLYROLL_DEM3D_DIR", "dem3d", source_dir});
}

double timeout_s() {
    if (const char* env = std::getenv("POLYROLL_DEM3D_TIMEOUT_S"); env && *env) {
        char* end = nullptr;
        const double t = std::strtod(env, &end);
        if (end == env || *end != '\0' || !(t > 0.0))
            throw InputError(fmt::format("POLYROLL_DEM3D_TIMEOUT_S={}: not a number of seconds above 0", env));
        return t;
    }
    return 7200.0;
}

namespace {

// How to run the script: with the launcher's own Python importing Yade as a library from the folder
// the launcher puts on sys.path (Debian's /usr/bin/yade: "#!/usr/bin/python3" and
// "sys.path.insert(1,'/usr/lib/x86_64-linux-gnu/yade-double/py')"), so that none of the launcher's
// servers start: its XMLRPC info server listens on every network interface while a run lasts. A
// launcher this cannot read runs the script itself ("yade -jN -n -x").
struct Launch {
    std::vector<std::string> argv;
    std::string yade_py;  // for POLYROLL_YADE_PY; empty through the launcher
};

Launch launch_for(const std::string& yade, const std::string& script, const fs::path& dir, int n_threads) {
    std::ifstream in(yade);
    std::string line, python, py_dir;
    if (std::getline(in, line) && line.rfind("#!", 0) == 0) {
        python = line.substr(2);
        while (!python.empty() && std::isspace(static_cast<unsigned char>(python.back()))) python.pop_back();
    }
    for (int n = 0; n < 200 && std::getline(in, line); ++n) {
        const size_t at = line.find("sys.path.insert(");
        if (at == std::string::npos) continue;
        const size_t open = line.find('\'', at), close = open == std::string::npos ? open : line.find('\'', open + 1);
        if (close != std::string::npos) py_dir = line.substr(open + 1, close - open - 1);
        break;
    }
    const std::string in_json = (dir / "IN.json").string();
    if (!python.empty() && python.find(' ') == std::string::npos && executable(python) && !py_dir.empty() &&
        fs::is_directory(fs::path(py_dir) / "yade"))
        return {{python, script, in_json, dir.string()}, py_dir};
    return {{yade, "-j" + std::to_string(n_threads), "-n", "-x", script, in_json, dir.string()}, ""};
}

}  // namespace

int threads() {
    if (const char* env = std::getenv("POLYROLL_DEM3D_THREADS"); env && *env) {
        char* end = nullptr;
        const long n = std::strtol(env, &end, 10);
        if (end == env || *end != '\0' || n < 1 || n > 64)
            throw InputError(fmt::format("POLYROLL_DEM3D_THREADS={}: allowed: a whole number from 1 to 64 (unset it "
                                         "for one thread, or a Slurm task's cores)", env));
        return static_cast<int>(n);
    }
    // More than one only on cores reserved for the run (a Slurm allocation): threads change a run's
    // numbers from one time to the next, and on cores shared with other work Yade's threads wait for
    // each other far longer than they compute (docs/physics.md has both measured).
    return in_allocation() ? std::min(run_cores(), 64) : 1;
}

int run_script(const nlohmann::ordered_json& input, const fs::path& dir) {
    const std::string yade = yade_command();
    const std::string script = script_path();
    const double limit_s = timeout_s();
    write_file_atomic(dir / "IN.json", input.dump(2) + "\n");
    // Yade's OpenMP threads: one gives the same numbers for a seed every time; more split its
    // interaction loops between cores, and then the order of the force sums, and the numbers, vary.
    const int n_threads = threads();
    const Launch launch = launch_for(yade, script, dir, n_threads);

    process::ChildOptions options{.own_process_group = true, .dies_with_parent = true};
    options.environment = {{"OMP_NUM_THREADS", std::to_string(n_threads)}};
    if (!launch.yade_py.empty()) options.environment.emplace_back("POLYROLL_YADE_PY", launch.yade_py);
    options.time_limit_s = limit_s;
    options.keep_stderr = true;
    // A caller that can be interrupted (the Python module: Ctrl-C) is asked while Yade works.
    if (run_stop_hooked()) options.should_stop = [] { return run_stop_requested(); };
    // Anything but "progress <t> <x>" on stdout is Yade's own chatter.
    options.on_output_line = [](const std::string& line) {
        double t = 0.0, x = 0.0;
        if (std::sscanf(line.c_str(), "progress %lf %lf", &t, &x) == 2) report_run_progress(t, x);
    };
    const process::ChildExit e = process::run_child(launch.argv, options);
    if (!e.started) throw std::runtime_error("cannot start Yade: " + e.why_not);
    if (e.stopped) throw RunStopped("the 3D reference was stopped before its end");
    const std::string& err_text = e.stderr_tail;
    if (e.timed_out)
        throw std::runtime_error(fmt::format("the 3D reference took longer than {:.0f} s and was stopped (set "
                                             "POLYROLL_DEM3D_TIMEOUT_S for more)", limit_s));
    if (!e.succeeded()) {
        const std::string why = last_line(err_text);
        const std::string how = e.how_it_ended();
        if (e.exit_code == 2) throw InputError("the 3D reference refused the scene: " + why);
        throw std::runtime_error(fmt::format("the 3D reference (Yade) failed ({}): {}", how,
                                             why.empty() ? tail(err_text, 400) : why));
    }
    return n_threads;
}

}  // namespace polyroll::dem3d
