// Running Yade: see yade_process.h.
#include "sim/dem3d/yade_process.h"

#include <cctype>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include "sim/atomic_file.h"
#include "sim/errors.h"
#include "sim/installed_script.h"

namespace polyroll::dem3d {

namespace fs = std::filesystem;

namespace {

thread_local Progress t_progress;

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
    if (const char* path = std::getenv("PATH")) {
        std::istringstream dirs(path);
        std::string dir;
        while (std::getline(dirs, dir, ':'))
            if (!dir.empty() && executable(fs::path(dir) / "yade")) return (fs::path(dir) / "yade").string();
    }
    throw InputError("--model dem3d needs Yade, which is not installed: run third_party/setup.sh (or apt-get install "
                     "yade) as root");
}

std::string script_path() {
#ifdef POLYROLL_DEM3D_SOURCE_DIR
    const char* source_dir = POLYROLL_DEM3D_SOURCE_DIR;
#else
    const char* source_dir = nullptr;
#endif
    return installed_script(
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

Progress set_progress(Progress p) {
    std::swap(t_progress, p);
    return p;
}

namespace {

// How to run the script: with the launcher's own Python importing Yade as a library from the folder
// the launcher puts on sys.path (Debian's /usr/bin/yade: "#!/usr/bin/python3" and
// "sys.path.insert(1,'/usr/lib/x86_64-linux-gnu/yade-double/py')"), so that none of the launcher's
// servers start: its XMLRPC info server listens on every network interface while a run lasts. A
// launcher this cannot read runs the script itself ("yade -j1 -n -x").
struct Launch {
    std::vector<std::string> argv;
    std::string yade_py;  // for POLYROLL_YADE_PY; empty through the launcher
};

Launch launch_for(const std::string& yade, const std::string& script, const fs::path& dir) {
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
    return {{yade, "-j1", "-n", "-x", script, in_json, dir.string()}, ""};
}

}  // namespace

void run_script(const nlohmann::ordered_json& input, const fs::path& dir) {
    const std::string yade = yade_command();
    const std::string script = script_path();
    const double limit_s = timeout_s();
    write_file_atomic(dir / "IN.json", input.dump(2) + "\n");
    const Launch launch = launch_for(yade, script, dir);

    int out_pipe[2], err_pipe[2];
    if (::pipe2(out_pipe, O_CLOEXEC) != 0 || ::pipe2(err_pipe, O_CLOEXEC) != 0)
        throw std::runtime_error("cannot start Yade (no pipe)");
    std::vector<char*> cargs;
    for (const auto& a : launch.argv) cargs.push_back(const_cast<char*>(a.c_str()));
    cargs.push_back(nullptr);
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("cannot start Yade (fork failed)");
    if (pid == 0) {
        // Its own process group, so a Ctrl-C at the terminal reaches polyroll alone: a sweep lets its
        // runs in flight finish (the first Ctrl-C), and polyroll decides. It dies with the thread that
        // started it, so a Ctrl-C that stops polyroll, or a crash, never leaves Yade running.
        ::setpgid(0, 0);
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (::getppid() != parent) ::_exit(127);
        ::dup2(out_pipe[1], 1);
        ::dup2(err_pipe[1], 2);
        const int null = ::open("/dev/null", O_RDONLY);
        if (null >= 0) ::dup2(null, 0);
        ::setenv("OMP_NUM_THREADS", "1", 1);  // one thread: a seed gives the same run twice
        if (!launch.yade_py.empty()) ::setenv("POLYROLL_YADE_PY", launch.yade_py.c_str(), 1);
        ::execv(cargs[0], cargs.data());
        ::_exit(127);
    }
    ::close(out_pipe[1]);
    ::close(err_pipe[1]);

    std::string out_buf, err_text;
    const auto start = std::chrono::steady_clock::now();
    bool timed_out = false;
    pollfd fds[2] = {{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
    int open_fds = 2;
    while (open_fds > 0) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (elapsed > limit_s) {
            timed_out = true;
            ::kill(pid, SIGKILL);
            break;
        }
        if (::poll(fds, 2, 1000) < 0) continue;  // interrupted by a signal: look again
        char buf[4096];
        for (int k = 0; k < 2; ++k) {
            if (fds[k].fd < 0 || !(fds[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            const ssize_t got = ::read(fds[k].fd, buf, sizeof buf);
            if (got <= 0) {
                ::close(fds[k].fd);
                fds[k].fd = -1;
                --open_fds;
                continue;
            }
            if (k == 1) {
                err_text.append(buf, static_cast<size_t>(got));
                if (err_text.size() > 65536) err_text = err_text.substr(err_text.size() - 16384);
                continue;
            }
            out_buf.append(buf, static_cast<size_t>(got));
            size_t nl;
            while ((nl = out_buf.find('\n')) != std::string::npos) {
                const std::string line = out_buf.substr(0, nl);
                out_buf.erase(0, nl + 1);
                double t = 0.0, x = 0.0;
                // Anything but "progress <t> <x>" is Yade's own chatter.
                if (t_progress && std::sscanf(line.c_str(), "progress %lf %lf", &t, &x) == 2) t_progress(t, x);
            }
        }
    }
    for (pollfd& f : fds)
        if (f.fd >= 0) ::close(f.fd);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
    }
    if (timed_out)
        throw std::runtime_error(fmt::format("the 3D reference took longer than {:.0f} s and was stopped (set "
                                             "POLYROLL_DEM3D_TIMEOUT_S for more)", limit_s));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        const std::string why = last_line(err_text);
        const std::string how = WIFEXITED(status) ? fmt::format("exit {}", WEXITSTATUS(status))
                                                  : fmt::format("signal {}", WTERMSIG(status));
        if (WIFEXITED(status) && WEXITSTATUS(status) == 2) throw InputError("the 3D reference refused the scene: " + why);
        throw std::runtime_error(fmt::format("the 3D reference (Yade) failed ({}): {}", how,
                                             why.empty() ? tail(err_text, 400) : why));
    }
}

}  // namespace polyroll::dem3d
