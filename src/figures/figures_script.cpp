// Running polyroll_figures.py: see figures_script.h.
#include "figures/figures_script.h"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include <fmt/core.h>

#include "process/child_process.h"
#include "process/installed_script.h"

namespace polyroll::figures {

namespace fs = std::filesystem;

namespace {

// Runs argv (argv[0] looked up on PATH) and returns its exit status as a shell would. A probe
// (silent) takes a program that cannot run as a failed one; the script's own run throws why.
int spawn(const std::vector<std::string>& argv, bool silent) {
    const process::ChildExit e = process::run_child(argv, {.search_path = true, .silent = silent});
    if (!e.started && !silent) throw std::runtime_error(e.why_not);
    return e.status();
}

}  // namespace

std::string figures_script() {
#ifdef POLYROLL_FIGURES_SOURCE_DIR
    const char* source_dir = POLYROLL_FIGURES_SOURCE_DIR;
#else
    const char* source_dir = nullptr;
#endif
    return process::installed_script({"polyroll_figures.py", "the figure script", "POLYROLL_FIGURES_DIR", "figures", source_dir});
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
