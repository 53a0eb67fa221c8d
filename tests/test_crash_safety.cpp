// Crash-safe output: runs, renders and sweeps are killed with SIGKILL at seeded moments; what
// is on disk must be whole files only (each equal to the uninterrupted result), and running the same
// command again must finish the job with nothing lost or duplicated. The moments are fractions of the
// uninterrupted command's own duration, so the test means the same on a fast build and under ASan.
#include <catch2/catch.hpp>

#include "sim/files/atomic_file.h"
#include "test_helpers.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <spawn.h>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

extern char** environ;

namespace fs = std::filesystem;

namespace {

using namespace polyroll::test;  // kPolyrollExe, read_file, table_without_wall_time

const polyroll::test::Scratch crash_scratch("crash-");

pid_t start(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    std::vector<std::string> all{kPolyrollExe};
    all.insert(all.end(), args.begin(), args.end());
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int rc = posix_spawn(&pid, kPolyrollExe.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    REQUIRE(rc == 0);
    return pid;
}

int wait_exit(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Runs to the end; returns the exit code and how long it took.
std::pair<int, double> run_whole(const std::vector<std::string>& args) {
    const auto t0 = std::chrono::steady_clock::now();
    const int code = wait_exit(start(args));
    return {code, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
}

// Starts the command and kills it with SIGKILL after `seconds` (or lets it finish first).
void run_and_kill(const std::vector<std::string>& args, double seconds) {
    const pid_t pid = start(args);
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    kill(pid, SIGKILL);
    wait_exit(pid);
}

// Seeded moments spread over (0, duration): deterministic, and covering early, middle and late kills.
std::vector<double> moments(unsigned seed, int count, double duration) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.05, 0.95);
    std::vector<double> m;
    for (int i = 0; i < count; ++i) m.push_back(u(rng) * duration);
    return m;
}

// The files people see (not the temporaries, whose names start with a dot), by name.
std::map<std::string, fs::path> visible_files(const fs::path& dir) {
    std::map<std::string, fs::path> files;
    std::error_code ec;
    for (const auto& e : fs::recursive_directory_iterator(dir, ec)) {
        const std::string name = e.path().filename().string();
        if (e.is_regular_file() && name[0] != '.') files[fs::relative(e.path(), dir).string()] = e.path();
    }
    return files;
}

// A file's content for comparison: summary.json without its wall time, which differs run to run.
std::string comparable(const fs::path& p) {
    const std::string text = read_file(p);
    if (p.filename() != "summary.json") return text;
    auto j = nlohmann::ordered_json::parse(text);  // throws (fails the test) on half a file
    j["results"].erase("wall_time_s");
    return j.dump();
}

// Every visible file in `dir` must be a whole file: the same as the uninterrupted result's.
void check_whole(const fs::path& dir, const fs::path& reference) {
    for (const auto& [name, path] : visible_files(dir)) {
        INFO(name);
        REQUIRE(fs::exists(reference / name));
        CHECK(comparable(path) == comparable(reference / name));
    }
}

// Temporaries left by killed writers: a finished command in the same folder must have removed them.
int temporaries(const fs::path& dir) {
    int n = 0;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec))
        n += e.path().filename().string().find(".tmp-") != std::string::npos;
    return n;
}

void check_same(const fs::path& dir, const fs::path& reference) {
    CHECK(temporaries(dir) == 0);
    const auto got = visible_files(dir), want = visible_files(reference);
    std::set<std::string> a, b;
    for (const auto& f : got) a.insert(f.first);
    for (const auto& f : want) b.insert(f.first);
    CHECK(a == b);
    check_whole(dir, reference);
}

}  // namespace

TEST_CASE("a run killed at random moments leaves whole files, and running it again completes it",
          "[hardening][crash-safety]") {
    const fs::path ref = crash_scratch("run-ref"), dir = crash_scratch("run");
    const std::vector<std::string> scene = {"run", "--fill", "0.5", "--time-limit", "12"};  // 41 faces, ~0.4 s
    auto with_out = [&](const fs::path& out, bool force) {
        auto a = scene;
        a.insert(a.end(), {"--out", out.string()});
        if (force) a.push_back("--force");
        return a;
    };
    const auto [code, duration] = run_whole(with_out(ref, false));
    REQUIRE(code == 0);
    REQUIRE(visible_files(ref).size() == 3);
    for (double t : moments(7, 5, duration)) {
        run_and_kill(with_out(dir, true), t);
        INFO("killed after " << t << " s of " << duration);
        check_whole(dir, ref);
    }
    REQUIRE(run_whole(with_out(dir, true)).first == 0);
    check_same(dir, ref);
    fs::remove_all(ref);
    fs::remove_all(dir);
}

TEST_CASE("a render killed at random moments leaves whole frames, and rendering again completes it",
          "[hardening][crash-safety]") {
    const fs::path ref = crash_scratch("render-ref"), dir = crash_scratch("render");
    auto args = [&](const fs::path& out, bool force) {
        std::vector<std::string> a = {"render", "--fill", "0.25", "--fidelity", "draft", "--time-limit", "1.5",
                                      "--size", "320x180", "--fps", "20", "--hold", "0", "--out", out.string()};
        if (force) a.push_back("--force");
        return a;
    };
    const auto [code, duration] = run_whole(args(ref, false));
    REQUIRE(code == 0);
    REQUIRE(visible_files(ref).size() > 10);
    for (double t : moments(11, 4, duration)) {
        run_and_kill(args(dir, true), t);
        INFO("killed after " << t << " s of " << duration);
        check_whole(dir, ref);  // frames are byte-identical for the same scene
    }
    REQUIRE(run_whole(args(dir, true)).first == 0);
    check_same(dir, ref);
    fs::remove_all(ref);
    fs::remove_all(dir);
}

namespace {

// results.csv: the header, then one row per run; returns the rows' first cells (the run index) after
// checking each row is whole (as many cells as the header, ends with a newline).
std::vector<std::string> table_indices(const fs::path& csv) {
    const std::string text = read_file(csv);
    REQUIRE(!text.empty());
    REQUIRE(text.back() == '\n');
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    const auto cells = [](const std::string& l) { return std::count(l.begin(), l.end(), ',') + 1; };
    const auto header_cells = cells(line);
    std::vector<std::string> indices;
    while (std::getline(in, line)) {
        CHECK(cells(line) == header_cells);  // a simple grid has no quoted commas
        indices.push_back(line.substr(0, line.find(',')));
    }
    return indices;
}

}  // namespace

TEST_CASE("a sweep killed at random moments resumes with the same command, nothing lost or duplicated",
          "[hardening][crash-safety]") {
    const fs::path ref = crash_scratch("sweep-ref"), dir = crash_scratch("sweep");
    auto args = [&](const fs::path& out) {
        return std::vector<std::string>{"sweep", "--sides", "6,8", "--fill", "0,0.125", "--angle", "10,25",
                                        "--fidelity", "draft", "--time-limit", "0.8", "-q", "--jobs", "2",
                                        "--out", out.string()};
    };
    const auto [code, duration] = run_whole(args(ref));
    REQUIRE(code == 0);
    const auto want = table_indices(ref / "results.csv");
    REQUIRE(want.size() == 8);
    for (double t : moments(13, 4, duration)) {
        run_and_kill(args(dir), t);
        INFO("killed after " << t << " s of " << duration);
        if (fs::exists(dir / "results.csv")) {
            auto got = table_indices(dir / "results.csv");
            const std::set<std::string> unique(got.begin(), got.end());
            CHECK(unique.size() == got.size());  // no run twice
            // A whole table: it ends on a complete line and each row is the uninterrupted sweep's row.
            const std::string text = read_file(dir / "results.csv");
            REQUIRE_FALSE(text.empty());
            CHECK(text.back() == '\n');
            const std::string ref_rows = table_without_wall_time(read_file(ref / "results.csv"));
            std::istringstream rows(table_without_wall_time(text));
            for (std::string row; std::getline(rows, row);) {
                INFO(row);
                CHECK(ref_rows.find(row + "\n") != std::string::npos);
            }
        }
        if (fs::exists(dir / "plan.json")) CHECK_NOTHROW(nlohmann::json::parse(read_file(dir / "plan.json")));
    }
    REQUIRE(run_whole(args(dir)).first == 0);
    auto got = table_indices(dir / "results.csv");
    std::sort(got.begin(), got.end());
    auto sorted_want = want;
    std::sort(sorted_want.begin(), sorted_want.end());
    CHECK(got == sorted_want);
    CHECK(table_without_wall_time(read_file(dir / "results.csv")) == table_without_wall_time(read_file(ref / "results.csv")));
    fs::remove_all(ref);
    fs::remove_all(dir);
}

// A command killed in its first moments can leave only its write probe or a temporary in a folder it
// just made (the sweep test above hit it: 1 of 17 runs refused the same command as "not empty").
TEST_CASE("a folder holding only a killed process's probe or temporary is used again as empty",
          "[hardening][crash-safety]") {
    const fs::path dir = crash_scratch("leftovers");
    fs::create_directories(dir);
    // 999999999 is above Linux's largest pid (2^22), so no process holds these names.
    for (const char* name : {".polyroll-probe-999999999", ".plan.json.tmp-999999999"}) {
        INFO(name);
        std::ofstream(dir / name) << "x";
        const std::vector<std::string> args{"sweep", "--sides", "6", "--fill", "0", "--angle", "25",
                                            "--fidelity", "draft", "--time-limit", "0.2", "-q", "--out", dir.string()};
        CHECK(run_whole(args).first == 0);
        CHECK(!fs::exists(dir / name));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    fs::remove_all(dir);
}

TEST_CASE("commands creating the same new output folder at once all proceed (shards started together)",
          "[hardening][crash-safety]") {
    // Two calibration shards started side by side both found the folder missing; the one that lost
    // the race to create it stopped with "cannot create the folder (unknown error)", and the other
    // waited for it for ever. Each round races threads on one new folder; every one must be let in.
    const fs::path base = crash_scratch("same-folder");
    for (int round = 0; round < 20; ++round) {
        const fs::path dir = base / std::to_string(round) / "out";
        std::vector<std::thread> threads;
        std::vector<int> failed(4, 0);
        for (size_t t = 0; t < failed.size(); ++t)
            threads.emplace_back([&, t] {
                try {
                    polyroll::prepare_output_dir(dir, true, "");
                } catch (const std::exception&) {
                    failed[t] = 1;
                }
            });
        for (std::thread& t : threads) t.join();
        INFO("round " << round);
        CHECK(std::count(failed.begin(), failed.end(), 1) == 0);
        CHECK(fs::is_directory(dir));
    }
    fs::remove_all(base);
}

TEST_CASE("Ctrl-C in run and render says so in one line and leaves no folder behind", "[hardening][cli]") {
    const fs::path dir = crash_scratch("ctrl-c");
    fs::create_directories(dir);
    // Both still running after 1.5 s: the large hexagon half full steps 1,488 grains (about 30 s), and a
    // render's data run of the default scene takes about 2.5 s before the first frame.
    for (const std::string& cmd : {std::string("run --polygon hexagon-large --fill 0.5"), std::string("render")}) {
        const fs::path out = dir / "out";
        const auto r = polyroll::test::run_command("timeout --preserve-status -s INT 1.5 " + kPolyrollExe + " " + cmd +
                                                   " --out " + out.string());
        INFO(cmd << "\n" << r.out);
        CHECK(r.exit_code == 130);
        CHECK_THAT(r.out, Catch::Contains("interrupted (Ctrl-C); the folder") && Catch::Contains("is removed"));
        CHECK(polyroll::test::line_count(r.out) == (cmd == "render" ? 2u : 1u));  // render's first line, then this
        CHECK_FALSE(fs::exists(out));
    }
    // A folder the command did not make is not removed (--force into an existing one).
    fs::create_directories(dir / "mine");
    std::ofstream(dir / "mine" / "notes.txt") << "kept\n";
    const auto kept = polyroll::test::run_command("timeout --preserve-status -s INT 1.5 " + kPolyrollExe +
                                                  " run --polygon hexagon-large --fill 0.5 --force --out " +
                                                  (dir / "mine").string());
    INFO(kept.out);
    CHECK(kept.exit_code == 130);
    CHECK(read_file(dir / "mine" / "notes.txt") == "kept\n");
    fs::remove_all(dir);
}
