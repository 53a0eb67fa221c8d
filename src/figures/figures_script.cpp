// Running polyroll_figures.py: see figures_script.h.
#include "figures/figures_script.h"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include "sim/installed_script.h"

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
#ifdef POLYROLL_FIGURES_SOURCE_DIR
    const char* source_dir = POLYROLL_FIGURES_SOURCE_DIR;
#else
    const char* source_dir = nullptr;
#endif
    return installed_script({"polyroll_figures.py", "the figure script", "POLYROLL_FIGURES_DIR", "figures", source_dir});
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
