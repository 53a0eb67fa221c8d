// Crash-safe recording of a results table: see table_writer.h.
#include "sweep/table_writer.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/core.h>

#include "sim/files/atomic_file.h"
#include "sim/errors.h"
#include "sweep/results_table.h"

namespace polyroll::sweep {

TableWriter::TableWriter(std::filesystem::path path, const std::vector<std::string>& header, bool drop_failed,
                         std::chrono::milliseconds max_commit_delay)
    : path_(std::move(path)), header_(header), max_commit_delay_(max_commit_delay) {
    const std::string lock = lock_path();
    // The lock file is removed when the table is closed (an empty results.csv.lock left in every sweep
    // folder read as a sweep still running). A writer may thus lock a file another has just removed:
    // the lock counts only when the name still leads to the locked file, else it tries again.
    for (;;) {
        lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (lock_fd_ < 0)
            throw InputError(fmt::format("{}: cannot be created ({})", lock, std::strerror(errno)));
        if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
            ::close(lock_fd_);
            lock_fd_ = -1;
            throw InputError(fmt::format("{}: another polyroll sweep is writing it (allowed: one writer per table; "
                                         "wait for it or stop it)", path_.string()));
        }
        struct stat held {}, named {};
        if (::fstat(lock_fd_, &held) == 0 && ::stat(lock.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
            held.st_ino == named.st_ino)
            break;
        ::close(lock_fd_);  // removed or replaced after we opened it: not the table's lock any more
        lock_fd_ = -1;
    }
    try {
        TableFile t = read_table(path_);
        if (!t.header.empty() && t.header != header_)
            throw InputError(fmt::format("{}: its columns differ from this sweep's (a table of another sweep?)",
                                         path_.string()));
        const std::size_t status = find_column(header_, "status").value();  // a results table's own column
        for (auto& row : t.rows)
            if (!(drop_failed && row.at(status) == "failed")) existing_.push_back(std::move(row));
        std::lock_guard<std::mutex> g(mutex_);
        commit_locked();  // a table (if only its header) exists from the start, and a bad folder fails now
        open_ = true;
    } catch (...) {
        release_lock();
        throw;
    }
    flusher_ = std::thread([this] { flush_loop(); });
}

TableWriter::~TableWriter() {
    {
        std::lock_guard<std::mutex> g(mutex_);
        // Left without close_sorted (an exception on the way out): keep the finished rows if the
        // disk lets us; if it does not, the next run of the sweep makes them again.
        if (open_ && dirty_) {
            try {
                commit_locked();
            } catch (...) {
            }
        }
        open_ = false;
    }
    wake_.notify_all();
    if (flusher_.joinable()) flusher_.join();
    release_lock();
}

std::string TableWriter::lock_path() const { return path_.string() + ".lock"; }

void TableWriter::release_lock() {
    if (lock_fd_ < 0) return;
    // Removed while still held, so no other writer can hold it (see the constructor).
    ::unlink(lock_path().c_str());
    ::close(lock_fd_);
    lock_fd_ = -1;
}

void TableWriter::commit_locked() {
    std::vector<std::vector<std::string>> rows = existing_;
    rows.insert(rows.end(), written_.begin(), written_.end());
    const auto start = std::chrono::steady_clock::now();
    write_file_atomic(path_, table_text(header_, std::move(rows)));
    const auto end = std::chrono::steady_clock::now();
    dirty_ = false;
    // Replacing the table may take at most a tenth of the time: wait nine times what it cost.
    next_commit_ = end + std::min<std::chrono::steady_clock::duration>(9 * (end - start), max_commit_delay_);
}

void TableWriter::flush_loop() {
    std::unique_lock<std::mutex> g(mutex_);
    while (open_) {
        if (!dirty_) {
            wake_.wait(g);
            continue;
        }
        if (std::chrono::steady_clock::now() < next_commit_) {
            wake_.wait_until(g, next_commit_);
            continue;
        }
        try {
            commit_locked();
        } catch (...) {
            flush_error_ = std::current_exception();
            return;
        }
    }
}

void TableWriter::append(const std::string& line) {
    {
        std::lock_guard<std::mutex> g(mutex_);
        if (flush_error_) std::rethrow_exception(flush_error_);
        if (!open_) throw std::logic_error("TableWriter::append after close_sorted");
        std::string body = line;
        if (!body.empty() && body.back() == '\n') body.pop_back();
        written_.push_back(parse_csv_line(body));
        dirty_ = true;
        if (std::chrono::steady_clock::now() >= next_commit_) commit_locked();
    }
    wake_.notify_all();  // the flusher replaces the table later if it was not due now
}

void TableWriter::replace_rows(std::vector<std::vector<std::string>> rows) {
    std::lock_guard<std::mutex> g(mutex_);
    existing_ = std::move(rows);
    written_.clear();
    dirty_ = true;
}

void TableWriter::close_sorted() {
    {
        std::lock_guard<std::mutex> g(mutex_);
        if (!open_) return;
        open_ = false;
    }
    wake_.notify_all();
    flusher_.join();
    std::lock_guard<std::mutex> g(mutex_);
    if (flush_error_) std::rethrow_exception(flush_error_);
    commit_locked();
    release_lock();
}

}  // namespace polyroll::sweep
