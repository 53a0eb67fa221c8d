// Saving screenshots and runs from the sandbox: see export_files.h.
#include "app/export_files.h"

#include <fmt/core.h>

#include "sim/files/results_io.h"

namespace polyroll::app {

namespace fs = std::filesystem;

fs::path next_numbered(const fs::path& dir, const std::string& stem, const std::string& ext) {
    for (int k = 1;; ++k) {
        fs::path p = dir / fmt::format("{}-{:03d}{}", stem, k, ext);
        std::error_code ec;
        if (!fs::exists(p, ec)) return p;
    }
}

std::vector<fs::path> export_runs(const fs::path& folder, const std::vector<RunResult>& runs) {
    std::vector<fs::path> written;
    for (size_t i = 0; i < runs.size(); ++i) {
        const fs::path dir = runs.size() == 1 ? folder : folder / fmt::format("lane-{}", i + 1);
        std::error_code ec;
        fs::create_directories(dir, ec);
        if (ec) throw std::runtime_error(fmt::format("cannot create {}: {}", dir.string(), ec.message()));
        write_run_files(dir, runs[i]);
        written.push_back(dir);
    }
    return written;
}

}  // namespace polyroll::app
