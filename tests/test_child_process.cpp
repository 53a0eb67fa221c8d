// Starting other programs (process/child_process.h): how a child ended, what it said, its limits.
#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "process/child_process.h"

using namespace polyroll::process;

TEST_CASE("run_child: the exit status and the lines a child writes") {
    std::vector<std::string> lines;
    ChildOptions o;
    o.on_output_line = [&](const std::string& line) { lines.push_back(line); };
    o.keep_stderr = true;
    const ChildExit e = run_child({"/bin/sh", "-c", "echo one; echo two; echo said >&2; exit 3"}, o);
    CHECK(e.started);
    CHECK_FALSE(e.succeeded());
    CHECK(e.exit_code == 3);
    CHECK(e.status() == 3);
    CHECK(e.how_it_ended() == "exit 3");
    CHECK(lines == std::vector<std::string>{"one", "two"});
    CHECK(e.stderr_tail == "said\n");
}

TEST_CASE("run_child: a program that cannot be executed is told apart from one that fails") {
    const ChildExit missing = run_child({"/nonexistent/polyroll-no-such-program"});
    CHECK_FALSE(missing.started);
    CHECK(missing.status() == 127);
    CHECK(missing.why_not.find("/nonexistent/polyroll-no-such-program") != std::string::npos);
    CHECK(missing.why_not.find("No such file") != std::string::npos);
    // A bare name is looked up on PATH only when asked.
    CHECK_FALSE(run_child({"sh", "-c", "exit 0"}).started);
    CHECK(run_child({"sh", "-c", "exit 0"}, {.search_path = true}).succeeded());
}

TEST_CASE("run_child: the environment it is given and stdin closed") {
    std::vector<std::string> lines;
    ChildOptions o;
    o.environment = {{"POLYROLL_CHILD_TEST", "42"}, {"HOME", "/child-home"}};
    o.on_output_line = [&](const std::string& line) { lines.push_back(line); };
    // `read` on /dev/null fails at once: a child never waits on polyroll's terminal.
    const ChildExit e =
        run_child({"/bin/sh", "-c", "echo $POLYROLL_CHILD_TEST $HOME; if read x; then echo read; else echo eof; fi"}, o);
    REQUIRE(e.succeeded());
    CHECK(lines == std::vector<std::string>{"42 /child-home", "eof"});
}

TEST_CASE("run_child: a child past its time limit is killed, with or without output to read") {
    ChildOptions reading;
    reading.time_limit_s = 0.3;
    reading.keep_stderr = true;
    const ChildExit a = run_child({"/bin/sh", "-c", "exec sleep 30"}, reading);
    CHECK(a.started);
    CHECK(a.timed_out);
    CHECK_FALSE(a.succeeded());
    const ChildExit b = run_child({"/bin/sh", "-c", "exec sleep 30"}, {.time_limit_s = 0.3});
    CHECK(b.timed_out);
    CHECK(b.how_it_ended() == "stopped at its time limit");
}

TEST_CASE("find_on_path and sibling_executable") {
    CHECK(find_on_path("sh").find("/sh") != std::string::npos);
    CHECK(find_on_path("polyroll-no-such-program").empty());
    const std::string sibling = sibling_executable("polyroll");
    CHECK(sibling.size() > std::string("/polyroll").size());
    CHECK(sibling.substr(sibling.size() - 9) == "/polyroll");
}

TEST_CASE("run_child: should_stop kills the child and what it started and says so") {
    // The Python module's Ctrl-C reaches a 3D run this way: the child is killed within about 0.2 s,
    // and with its own process group the programs it started too (here the shell's sleep).
    int asked = 0;
    std::string grandchild_pid;
    ChildOptions o;
    o.own_process_group = true;
    o.keep_stderr = true;
    o.on_output_line = [&grandchild_pid](const std::string& line) { grandchild_pid = line; };
    o.should_stop = [&asked, &grandchild_pid] { return !grandchild_pid.empty() && ++asked >= 3; };
    const auto start = std::chrono::steady_clock::now();
    const ChildExit e = run_child({"/bin/sh", "-c", "sleep 30 & echo $!; wait"}, o);
    const double took_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(e.started);
    CHECK(e.stopped);
    CHECK_FALSE(e.timed_out);
    CHECK_FALSE(e.succeeded());
    CHECK(e.signal == 9);
    CHECK(asked == 3);
    CHECK(took_s < 10.0);  // not the child's 30 s: the bound is loose on purpose (a shared machine)
    // The sleep is gone (or a zombie waiting for init to reap it) within a few seconds, not 30.
    REQUIRE_FALSE(grandchild_pid.empty());
    const std::filesystem::path stat = "/proc/" + grandchild_pid + "/stat";
    auto alive = [&stat] {
        std::ifstream in(stat);
        std::string pid, name, state;
        return in >> pid >> name >> state && state != "Z";
    };
    for (int k = 0; k < 100 && alive(); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    CHECK_FALSE(alive());
    // Never asked to stop: it runs to its end.
    ChildOptions never;
    never.keep_stderr = true;
    never.should_stop = [] { return false; };
    CHECK(run_child({"/bin/sh", "-c", "exit 0"}, never).succeeded());
}
