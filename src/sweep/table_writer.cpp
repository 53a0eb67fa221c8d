// Crash-safe appending to a results table: see table_writer.h.
#include "sweep/table_writer.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <fmt/format.h>

#include "sim/atomic_file.h"
#include "sim/errors.h"
#include "sweep/results_table.h"

namespace polyroll::sweep {

TableWriter::TableWriter(std::filesystem::path path, const std::vector<std::string>& header, bool drop_failed)
    : path_(std::move(path)), header_(header) {
    const std::string lock = path_.string() + ".lock";
    lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (lock_fd_ < 0)
        throw InputError(fmt::format("{}: cannot be created ({})", lock, std::strerror(errno)));
    if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
        ::close(lock_fd_);
        lock_fd_ = -1;
        throw InputError(fmt::format("{}: another polyroll sweep is writing it (allowed: one writer per table; "
                                     "wait for it or stop it)", path_.string()));
    }
    try {
        TableFile t = read_table(path_);
        if (!t.header.empty() && t.header != header_)
            throw InputError(fmt::format("{}: its columns differ from this sweep's (a table of another sweep?)",
                                         path_.string()));
        const std::size_t status = static_cast<std::size_t>(
            std::find(header_.begin(), header_.end(), "status") - header_.begin());
        for (auto& row : t.rows)
            if (!(drop_failed && row.at(status) == "failed")) existing_.push_back(std::move(row));
        // Rewritten whole so the file ends on a complete line before anything is appended.
        std::string text = csv_line(header_);
        for (const auto& r : existing_) text += csv_line(r);
        write_file_atomic(path_, text);
        fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
        if (fd_ < 0) throw std::runtime_error(fmt::format("{}: cannot be opened ({})", path_.string(), std::strerror(errno)));
    } catch (...) {
        ::close(lock_fd_);
        lock_fd_ = -1;
        throw;
    }
}

TableWriter::~TableWriter() {
    if (fd_ >= 0) ::close(fd_);
    if (lock_fd_ >= 0) ::close(lock_fd_);
}

void TableWriter::append(const std::string& line) {
    std::lock_guard<std::mutex> g(mutex_);
    std::size_t done = 0;
    while (done < line.size()) {
        const ssize_t n = ::write(fd_, line.data() + done, line.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw std::runtime_error(fmt::format("{}: write failed ({})", path_.string(), std::strerror(errno)));
        done += static_cast<std::size_t>(n);
    }
    // On disk before the run counts as done: a power cut loses at most the runs still in flight.
    if (::fdatasync(fd_) != 0)
        throw std::runtime_error(fmt::format("{}: flush failed ({})", path_.string(), std::strerror(errno)));
    std::string body = line;
    if (!body.empty() && body.back() == '\n') body.pop_back();
    written_.push_back(parse_csv_line(body));
}

void TableWriter::replace_rows(std::vector<std::vector<std::string>> rows) {
    std::lock_guard<std::mutex> g(mutex_);
    existing_ = std::move(rows);
    written_.clear();
}

void TableWriter::close_sorted() {
    std::lock_guard<std::mutex> g(mutex_);
    if (fd_ < 0) return;
    ::close(fd_);
    fd_ = -1;
    std::vector<std::vector<std::string>> rows = existing_;
    rows.insert(rows.end(), written_.begin(), written_.end());
    write_file_atomic(path_, table_text(header_, rows));
    // The lock file stays: removing it would let a second writer lock a fresh file while a third
    // still holds the old one.
    ::close(lock_fd_);
    lock_fd_ = -1;
}

}  // namespace polyroll::sweep
