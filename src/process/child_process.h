// Starting other programs: the figures' Python, ffmpeg, Yade, and polyroll itself from the window
// without a display. One way to start a child, wait for it and read what it said, so that every
// caller gets the same care: stdin closed, an exec that fails told apart from a program that fails,
// Ctrl-C and a crash handled, and no zombie left behind.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace polyroll::process {

// The full path of `name` on PATH, or "" when no folder there holds an executable of that name.
std::string find_on_path(const std::string& name);

// `name` beside this program's own binary (/proc/self/exe), or plain `name` when that cannot be read.
std::string sibling_executable(const std::string& name);

struct ChildOptions {
    bool search_path = false;  // argv[0] may be a bare name, looked up on PATH
    bool silent = false;       // stdout and stderr to /dev/null (a probe: only the exit status matters)
    // Its own process group, so a Ctrl-C at the terminal reaches polyroll alone, which then decides
    // (a sweep lets its runs in flight finish). A time limit or should_stop then kills the whole group.
    bool own_process_group = false;
    // Killed when the thread that started it ends, so a polyroll stopped by Ctrl-C or a crash never
    // leaves it running.
    bool dies_with_parent = false;
    std::vector<std::pair<std::string, std::string>> environment{};  // set in the child only
    double time_limit_s = 0.0;  // killed after this many wall-clock seconds; 0: no limit
    // Called with each line the child writes on stdout (stdout is then read, not shown).
    std::function<void(const std::string& line)> on_output_line{};
    bool keep_stderr = false;  // read stderr (not shown) and keep its last 16 KB in ChildExit
    // Asked about every 0.2 s while the child runs (with on_output_line or keep_stderr): true kills it.
    std::function<bool()> should_stop{};
};

struct ChildExit {
    bool started = false;   // false: no process, or its program could not be executed (why_not says)
    std::string why_not;
    bool timed_out = false;  // killed at ChildOptions::time_limit_s
    bool stopped = false;    // killed because ChildOptions::should_stop said so
    int exit_code = -1;      // the exit status when it exited, else -1
    int signal = 0;          // the signal that ended it, else 0
    std::string stderr_tail;  // with keep_stderr

    bool succeeded() const { return started && !timed_out && !stopped && exit_code == 0; }
    // The shell's number: the exit status, 128 + the signal, or 127 when it never started.
    int status() const { return !started ? 127 : signal ? 128 + signal : exit_code; }
    // "exit 3" or "signal 9", for a message.
    std::string how_it_ended() const;
};

// Starts argv[0] with argv, waits for it and says how it ended. Never throws for the child's sake.
ChildExit run_child(const std::vector<std::string>& argv, const ChildOptions& options = {});

// Replaces this process with argv[0] (execv): returns only if that fails, with errno set.
void replace_process(const std::vector<std::string>& argv);

}  // namespace polyroll::process
