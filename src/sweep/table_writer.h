// Appending rows to a results table so that nothing is lost: the table is locked against a second
// writer, a line cut short by a crash is dropped on opening, and each row is written in one call
// and flushed to disk (fdatasync) before the next run is counted as done.
#pragma once

#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

namespace polyroll::sweep {

class TableWriter {
public:
    // Takes the lock (path + ".lock"; InputError if another process holds it), reads the rows already
    // there (InputError if the header is not `header`), drops failed rows when `drop_failed`, and
    // rewrites the table whole before appending to it.
    TableWriter(std::filesystem::path path, const std::vector<std::string>& header, bool drop_failed);
    ~TableWriter();
    TableWriter(const TableWriter&) = delete;
    TableWriter& operator=(const TableWriter&) = delete;

    const std::vector<std::vector<std::string>>& existing_rows() const { return existing_; }

    // Thread-safe. Throws std::runtime_error naming the file if the write fails.
    void append(const std::string& line);

    // Replaces every row (existing and appended) with `rows`, to be written by close_sorted.
    void replace_rows(std::vector<std::vector<std::string>> rows);

    // Rewrites the table sorted by index (atomically) and releases the lock.
    void close_sorted();

private:
    std::filesystem::path path_;
    std::vector<std::string> header_;
    std::vector<std::vector<std::string>> existing_;
    std::vector<std::vector<std::string>> written_;
    int fd_ = -1;
    int lock_fd_ = -1;
    std::mutex mutex_;
};

}  // namespace polyroll::sweep
