// Recording a sweep's rows so that nothing is lost and nothing is ever half-written: the table is
// locked against a second writer, and it is only ever replaced whole (written under a temporary name,
// synced, renamed into place; see sim/files/atomic_file.h), never appended to in place. Finished rows are
// kept in memory; the table is replaced when a row finishes, unless the last replacement was so
// recent that replacing again would cost more than a tenth of the time (a table of thousands of rows
// takes milliseconds to write and sync), and at most a second after a row finished. A killed sweep
// thus loses at most about a second of rows, which the next run of the same command makes again.
#pragma once

#include <chrono>
#include <condition_variable>
#include <exception>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace polyroll::sweep {

// The longest a finished row waits in memory before the table is replaced.
inline constexpr std::chrono::milliseconds kTableMaxCommitDelay{1000};

class TableWriter {
public:
    // Takes the lock (path + ".lock", removed when closed; InputError if another process holds it),
    // reads the rows already there (InputError if the header is not `header`), drops failed rows when
    // `drop_failed`, and replaces the table with what it kept (a line cut short by an older polyroll is
    // dropped).
    TableWriter(std::filesystem::path path, const std::vector<std::string>& header, bool drop_failed,
                std::chrono::milliseconds max_commit_delay = kTableMaxCommitDelay);
    ~TableWriter();
    TableWriter(const TableWriter&) = delete;
    TableWriter& operator=(const TableWriter&) = delete;

    const std::vector<std::vector<std::string>>& existing_rows() const { return existing_; }

    // Thread-safe. Records a finished row (a csv line) and replaces the table on disk when it is due
    // (see above). Throws std::runtime_error naming the file if that write fails.
    void append(const std::string& line);

    // Replaces every row (existing and appended) with `rows`, to be written by close_sorted.
    void replace_rows(std::vector<std::vector<std::string>> rows);

    // Replaces the table with every row (sorted by index) and releases the lock.
    void close_sorted();

private:
    void commit_locked();  // mutex_ held
    std::string lock_path() const;
    void release_lock();   // removes the lock file, then lets it go
    void flush_loop();     // the flusher thread: replaces the table when rows have waited long enough


    std::filesystem::path path_;
    std::vector<std::string> header_;
    std::vector<std::vector<std::string>> existing_;
    std::vector<std::vector<std::string>> written_;
    std::chrono::steady_clock::duration max_commit_delay_;
    std::chrono::steady_clock::time_point next_commit_;
    bool open_ = false;
    bool dirty_ = false;                // rows recorded since the last replacement
    std::exception_ptr flush_error_;    // the flusher's failure, rethrown by append and close_sorted
    int lock_fd_ = -1;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::thread flusher_;
};

}  // namespace polyroll::sweep
