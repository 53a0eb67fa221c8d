// Finding a script polyroll runs: see installed_script.h.
#include "process/installed_script.h"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <fmt/core.h>

namespace polyroll::process {

namespace fs = std::filesystem;

std::string installed_script(const ScriptPlaces& p) {
    std::vector<fs::path> tried;
    if (const char* env = std::getenv(p.env_dir)) tried.push_back(fs::path(env) / p.name);
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) tried.push_back(exe.parent_path().parent_path() / "share" / "polyroll" / p.share_dir / p.name);
    if (p.source_dir != nullptr) tried.push_back(fs::path(p.source_dir) / p.name);
    std::string list;
    for (const fs::path& path : tried) {
        if (fs::is_regular_file(path, ec)) return path.string();
        list += (list.empty() ? "" : ", ") + path.string();
    }
    throw std::runtime_error(fmt::format("{} {} is not installed (tried: {}; set {} to the folder holding it)", p.what,
                                         p.name, list, p.env_dir));
}

}  // namespace polyroll::process
