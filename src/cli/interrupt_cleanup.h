// Ctrl-C (or SIGTERM) during a single run or render: one line says what happened, the folder the
// command created for its files is removed (a run writes its files only at the end, so an
// interrupted one holds nothing whole; a render's frames would be half a sequence), and the
// command exits 130. Sweeps stop more gently (interruptible_sweep.h): they resume.
#pragma once

#include <atomic>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>

namespace polyroll::cli {

class CleanUpOnInterrupt {
public:
    // `command` names the command in the line ("polyroll run"); `created` the folder this command
    // made (none: nothing is removed, a folder it did not make is never touched).
    CleanUpOnInterrupt(std::string command, std::optional<std::filesystem::path> created);
    ~CleanUpOnInterrupt();  // the previous handlers back, the watcher stopped
    CleanUpOnInterrupt(const CleanUpOnInterrupt&) = delete;
    CleanUpOnInterrupt& operator=(const CleanUpOnInterrupt&) = delete;

private:
    void watch();

    std::string command_;
    std::optional<std::filesystem::path> created_;
    std::atomic<bool> done_{false};
    void (*old_int_)(int);
    void (*old_term_)(int);
    std::thread watcher_;
};

}  // namespace polyroll::cli
