// The no-display fallback: see headless_fallback.h.
#include "app/headless_fallback.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unistd.h>

#include <fmt/format.h>

namespace polyroll::app {

std::string sibling_polyroll() {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return "polyroll";
    return (self.parent_path() / "polyroll").string();
}

int run_headless_instead(const std::string& why) {
    const std::string exe = sibling_polyroll();
    fmt::print("polyroll-sandbox: no display ({}): rendering the default scene headless instead "
               "(polyroll render --out runs/default --force)\n",
               why);
    std::fflush(stdout);
    std::fflush(stderr);
    const char* argv[] = {exe.c_str(), "render", "--out", "runs/default", "--force", nullptr};
    ::execv(exe.c_str(), const_cast<char* const*>(argv));
    fmt::print(stderr, "polyroll-sandbox: could not run {}: {}\n", exe, std::strerror(errno));
    return 1;
}

}  // namespace polyroll::app
