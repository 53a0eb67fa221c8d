// Whole-or-nothing file writes: see atomic_file.h.
#include "sim/files/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <csignal>
#include <regex>
#include <fcntl.h>
#include <unistd.h>

#include <fmt/core.h>

#include "sim/errors.h"

namespace polyroll {

namespace fs = std::filesystem;

void write_file_atomic(const fs::path& path, std::string_view content, Durability durability) {
    const fs::path tmp = path.parent_path() / fmt::format(".{}.tmp-{}", path.filename().string(), ::getpid());
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw std::runtime_error(fmt::format("cannot write {}: {}", path.string(), std::strerror(errno)));
    size_t done = 0;
    while (done < content.size()) {
        const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            const int err = errno;
            ::close(fd);
            ::unlink(tmp.c_str());
            throw std::runtime_error(fmt::format("cannot write {}: {}", path.string(), std::strerror(err)));
        }
        done += static_cast<size_t>(n);
    }
    // Data on disk before the rename makes it visible, so a power cut cannot leave an empty file.
    const bool synced = durability == Durability::unsynced || ::fsync(fd) == 0;
    if (!synced || ::close(fd) != 0 || ::rename(tmp.c_str(), path.c_str()) != 0) {
        const int err = errno;
        ::unlink(tmp.c_str());
        throw std::runtime_error(fmt::format("cannot write {}: {}", path.string(), std::strerror(err)));
    }
}

namespace {

// A killed writer leaves its temporary behind (never half a file under the real name), and a process
// killed between creating and removing its write probe leaves the probe. When the folder is used
// again they are removed, unless the process that wrote one is still running; before the folder is
// judged empty, so that a command killed in its first moments can be run again as it was.
void remove_stale_temporaries(const fs::path& dir) {
    static const std::regex temporary(R"((?:\..+\.tmp-|\.polyroll-probe-)(\d{1,9})(\..*)?)");
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        const std::string name = e.path().filename().string();
        std::smatch m;
        if (!std::regex_match(name, m, temporary)) continue;
        const auto pid = static_cast<pid_t>(std::stol(m[1].str()));
        if (pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH) fs::remove(e.path(), ec);
    }
}

}  // namespace

std::optional<fs::path> prepare_output_dir(const fs::path& dir, bool force, std::string_view remedy) {
    std::error_code ec;
    std::optional<fs::path> created;
    if (!fs::exists(dir, ec)) {
        // The first missing ancestor is what to remove if the run fails.
        fs::path top = fs::absolute(dir, ec).lexically_normal();
        if (!top.has_filename()) top = top.parent_path();
        while (top.has_parent_path() && top.parent_path() != top && !fs::exists(top.parent_path(), ec))
            top = top.parent_path();
        const bool made = fs::create_directories(dir, ec);
        if (ec)
            throw InputError(fmt::format("--out {}: cannot create the folder ({})", dir.string(), ec.message()));
        // Not made here without an error: another process made it a moment ago (two calibration or
        // sweep shards started together), so it is checked below as an existing folder.
        if (made) created = top;
    }
    if (!created) {
        if (!fs::is_directory(dir, ec))
            throw InputError(fmt::format("--out {}: exists and is not a folder", dir.string()));
        remove_stale_temporaries(dir);
        if (!force && !fs::is_empty(dir, ec))
            throw InputError(fmt::format("--out {}: folder exists and is not empty ({})", dir.string(), remedy));
    }
    const fs::path probe = dir / fmt::format(".polyroll-probe-{}", ::getpid());
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) {
        const int err = errno;
        if (created) fs::remove_all(*created, ec);
        throw InputError(fmt::format("--out {}: cannot write files there ({})", dir.string(), std::strerror(err)));
    }
    ::close(fd);
    ::unlink(probe.c_str());
    return created;
}

}  // namespace polyroll
