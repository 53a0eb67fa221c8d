// Running polyroll_figures.py: see figures_script.h.
#include "figures/figures_script.h"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

namespace polyroll::figures {

namespace fs = std::filesystem;

namespace {

int spawn(const std::vector<std::string>& argv, bool silent) {
    std::vector<char*> cargs;
    cargs.reserve(argv.size() + 1);
    for (const auto& a : argv) cargs.push_back(const_cast<char*>(a.c_str()));
    cargs.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("cannot start a process (fork failed)");
    if (pid == 0) {
        if (silent) {
            const int null = ::open("/dev/null", O_WRONLY);
            ::dup2(null, 1);
            ::dup2(null, 2);
        }
        ::execvp(cargs[0], cargs.data());
        ::_exit(127);
    }
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

std::string figures_script() {
    const char* name = "polyroll_figures.py";
    std::vector<fs::path> tried;
    if (const char* env = std::getenv("POLYROLL_FIGURES_DIR")) tried.push_back(fs::path(env) / name);
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) tried.push_back(exe.parent_path().parent_path() / "share" / "polyroll" / "figures" / name);
#ifdef POLYROLL_FIGURES_SOURCE_DIR
    tried.push_back(fs::path(POLYROLL_FIGURES_SOURCE_DIR) / name);
#endif
    std::string list;
    for (const fs::path& p : tried) {
        if (fs::is_regular_file(p, ec)) return p.string();
        list += (list.empty() ? "" : ", ") + p.string();
    }
    throw std::runtime_error(fmt::format("the figure script {} is not installed (tried: {}; set POLYROLL_FIGURES_DIR "
                                         "to the folder holding it)", name, list));
}

std::string figures_python() {
    std::vector<std::string> candidates;
    if (const char* env = std::getenv("POLYROLL_PYTHON")) candidates.emplace_back(env);
    else {
        if (fs::exists("/usr/bin/python3")) candidates.emplace_back("/usr/bin/python3");
        candidates.emplace_back("python3");
    }
    for (const std::string& py : candidates)
        if (spawn({py, "-c", "import matplotlib, numpy"}, true) == 0) return py;
    std::string list;
    for (const auto& c : candidates) list += (list.empty() ? "" : ", ") + c;
    throw std::runtime_error(fmt::format("figures need Python 3 with matplotlib and numpy, and {} cannot import them "
                                         "(install Debian's python3-matplotlib, or set POLYROLL_PYTHON)", list));
}

int run_figures_script(const std::vector<std::string>& args) {
    std::vector<std::string> argv = {figures_python(), figures_script()};
    argv.insert(argv.end(), args.begin(), args.end());
    return spawn(argv, false);
}

}  // namespace polyroll::figures
