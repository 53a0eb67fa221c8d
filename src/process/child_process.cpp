// Starting other programs: see child_process.h.
#include "process/child_process.h"

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <thread>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#if defined(__linux__)
#include <sys/prctl.h>
#endif

#include <fmt/core.h>

extern char** environ;

namespace polyroll::process {

namespace fs = std::filesystem;

std::string find_on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    if (!path) return {};
    const std::string dirs = path;
    size_t start = 0;
    while (start <= dirs.size()) {
        size_t end = dirs.find(':', start);
        if (end == std::string::npos) end = dirs.size();
        const std::string dir = dirs.substr(start, end - start);
        const fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
        std::error_code ec;
        if (::access(candidate.c_str(), X_OK) == 0 && fs::is_regular_file(candidate, ec)) return candidate.string();
        start = end + 1;
    }
    return {};
}

std::string sibling_executable(const std::string& name) {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return name;
    return (self.parent_path() / name).string();
}

std::string ChildExit::how_it_ended() const {
    if (!started) return why_not;
    if (timed_out) return "stopped at its time limit";
    return signal ? fmt::format("signal {}", signal) : fmt::format("exit {}", exit_code);
}

namespace {

// argv and the environment as the exec functions take them; built before fork, because the child of
// a threaded program may only make async-signal-safe calls (no allocation) until it execs.
struct ExecArgs {
    std::vector<std::string> env_strings;
    std::vector<char*> argv, envp;

    ExecArgs(const std::vector<std::string>& args, const ChildOptions& o) {
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        for (const auto& [key, value] : o.environment) env_strings.push_back(key + "=" + value);
        for (char** e = environ; e && *e; ++e) {
            bool replaced = false;
            for (const auto& kv : o.environment)
                replaced = replaced || (std::strncmp(*e, kv.first.c_str(), kv.first.size()) == 0 &&
                                        (*e)[kv.first.size()] == '=');
            if (!replaced) envp.push_back(*e);
        }
        for (std::string& s : env_strings) envp.push_back(s.data());
        envp.push_back(nullptr);
    }
};

void close_fd(int& fd) {
    if (fd >= 0) ::close(fd);
    fd = -1;
}

struct Pipe {
    int read = -1, write = -1;
    bool open() {
        int fds[2];
        if (::pipe2(fds, O_CLOEXEC) != 0) return false;
        read = fds[0];
        write = fds[1];
        return true;
    }
    ~Pipe() {
        close_fd(read);
        close_fd(write);
    }
};

// In the child, between fork and exec: async-signal-safe calls only.
[[noreturn]] void become_child(const ChildOptions& o, ExecArgs& a, pid_t parent, const Pipe& out, const Pipe& err,
                               const Pipe& exec_error) {
    if (o.own_process_group) ::setpgid(0, 0);
#if defined(__linux__)
    if (o.dies_with_parent) {
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (::getppid() != parent) ::_exit(127);  // the parent died before the line above
    }
#else
    (void)parent;
#endif
    // No child reads polyroll's terminal: a key pressed there is for polyroll.
    const int null_in = ::open("/dev/null", O_RDONLY);
    if (null_in >= 0) ::dup2(null_in, 0);
    if (o.silent) {
        const int null_out = ::open("/dev/null", O_WRONLY);
        if (null_out >= 0) {
            ::dup2(null_out, 1);
            ::dup2(null_out, 2);
        }
    }
    if (out.write >= 0) ::dup2(out.write, 1);
    if (err.write >= 0) ::dup2(err.write, 2);
    if (o.search_path)
        ::execvpe(a.argv[0], a.argv.data(), a.envp.data());
    else
        ::execve(a.argv[0], a.argv.data(), a.envp.data());
    const int why = errno;
    [[maybe_unused]] const ssize_t ignored = ::write(exec_error.write, &why, sizeof why);
    ::_exit(127);
}

// Kills the child, and with its own process group everything it started too (a shell's programs):
// killed alone, they would live on, holding the pipes polyroll or its caller reads.
void kill_child(pid_t pid, const ChildOptions& o) {
    if (o.own_process_group && ::kill(-pid, SIGKILL) == 0) return;
    ::kill(pid, SIGKILL);
}

// Reads the child's pipes until both close, the time limit passes (timed_out) or should_stop says so
// (stopped); the child is killed in the last two cases.
void read_pipes(pid_t pid, const ChildOptions& o, Pipe& out, Pipe& err, ChildExit& result) {
    std::string& err_text = result.stderr_tail;
    const auto start = std::chrono::steady_clock::now();
    std::string out_buf;
    pollfd fds[2] = {{out.read, POLLIN, 0}, {err.read, POLLIN, 0}};
    int open_fds = (out.read >= 0) + (err.read >= 0);
    while (open_fds > 0) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (o.time_limit_s > 0.0 && elapsed > o.time_limit_s) {
            kill_child(pid, o);
            result.timed_out = true;
            return;
        }
        if (o.should_stop && o.should_stop()) {
            kill_child(pid, o);
            result.stopped = true;
            return;
        }
        if (::poll(fds, 2, o.should_stop ? 200 : 1000) < 0) continue;  // interrupted by a signal: look again
        char buf[4096];
        for (int k = 0; k < 2; ++k) {
            if (fds[k].fd < 0 || !(fds[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            const ssize_t got = ::read(fds[k].fd, buf, sizeof buf);
            if (got <= 0) {
                close_fd(k == 0 ? out.read : err.read);
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
                o.on_output_line(line);
            }
        }
    }
}

// Waits for the child; with a time limit and nothing to read, polls so the limit can act.
int wait_for(pid_t pid, const ChildOptions& o, double time_limit_s, bool& timed_out) {
    int status = 0;
    if (time_limit_s > 0.0 && !timed_out) {
        const auto start = std::chrono::steady_clock::now();
        for (;;) {
            const pid_t got = ::waitpid(pid, &status, WNOHANG);
            if (got == pid) return status;
            if (got < 0 && errno != EINTR) return status;
            if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > time_limit_s) {
                kill_child(pid, o);
                timed_out = true;
                break;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
    }
    while (::waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) break;
    return status;
}

}  // namespace

ChildExit run_child(const std::vector<std::string>& argv, const ChildOptions& o) {
    ChildExit result;
#if defined(__EMSCRIPTEN__)
    (void)o;
    result.why_not = "a web page cannot start " + (argv.empty() ? std::string("programs") : argv[0]);
    return result;
#endif
    if (argv.empty()) {
        result.why_not = "nothing to run";
        return result;
    }
    Pipe out, err, exec_error;
    if (!exec_error.open() || (o.on_output_line && !out.open()) || (o.keep_stderr && !err.open())) {
        result.why_not = fmt::format("cannot start {} (no pipe: {})", argv[0], std::strerror(errno));
        return result;
    }
    ExecArgs args(argv, o);
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) {
        result.why_not = fmt::format("cannot start {} (fork: {})", argv[0], std::strerror(errno));
        return result;
    }
    if (pid == 0) become_child(o, args, parent, out, err, exec_error);
    // The parent sets the group too, so a kill of the group right after fork cannot miss the child.
    if (o.own_process_group) ::setpgid(pid, pid);
    close_fd(out.write);
    close_fd(err.write);
    close_fd(exec_error.write);
    // The exec-error pipe closes on a successful exec (O_CLOEXEC) and carries errno on a failed one.
    int exec_errno = 0;
    ssize_t got = 0;
    while ((got = ::read(exec_error.read, &exec_errno, sizeof exec_errno)) < 0 && errno == EINTR) {
    }
    if (got == sizeof exec_errno) {
        bool ignored = false;
        wait_for(pid, o, 0.0, ignored);
        result.why_not = fmt::format("cannot run {}: {}", argv[0], std::strerror(exec_errno));
        return result;
    }
    result.started = true;
    read_pipes(pid, o, out, err, result);
    bool timed_out = result.timed_out || result.stopped;  // killed already: only reaped here
    const int status = wait_for(pid, o, o.time_limit_s, timed_out);
    if (!result.stopped) result.timed_out = timed_out;
    if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    if (result.stderr_tail.size() > 16384) result.stderr_tail = result.stderr_tail.substr(result.stderr_tail.size() - 16384);
    return result;
}

void replace_process(const std::vector<std::string>& argv) {
    std::vector<char*> args;
    args.reserve(argv.size() + 1);
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execv(args[0], args.data());
}

}  // namespace polyroll::process
