// Shared helpers for the tests: scenes from the bundled defaults with a few fields changed, the
// programs run as a user runs them, scratch folders, and the check that bad input is refused.
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include <unistd.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "sim/errors.h"
#include "sim/model_registry.h"
#include "sim/scene/scene.h"
#include "sim/scene/scene_json.h"
#include "sim/grains/simulation.h"

namespace polyroll::test {

// Whether this build runs under AddressSanitizer: g++ says so by __SANITIZE_ADDRESS__, clang 14 only
// by __has_feature.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

// The default scene with `overrides` (a scene document) on top, resolved and validated.
inline Scene scene_with(const nlohmann::ordered_json& overrides) {
    return resolve_scene({SceneLayer{overrides, "test", {}}});
}

// The message `call` is refused with (an InputError); "" if it returns.
template <class Call>
std::string input_error_of(Call&& call) {
    try {
        call();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// The message a scene document (JSON text) is refused with; "" if it resolves.
inline std::string scene_error_of(const std::string& doc) {
    return input_error_of([&] { scene_with(nlohmann::ordered_json::parse(doc)); });
}

// The scene with another model (the rest unchanged).
inline Scene with_model(Scene s, Model m) {
    s.run.model = m;
    return s;
}

// What a command printed (stdout and stderr together) and how it exited, for the tests that run
// the programs as a user would.
struct CommandResult {
    int exit_code = -1;
    std::string out;
    double seconds = 0.0;  // wall time, start to exit
};

inline CommandResult run_command(const std::string& cmd) {
    CommandResult r;
    const auto start = std::chrono::steady_clock::now();
    FILE* pipe = popen((cmd + " 2>&1").c_str(), "r");
    if (pipe == nullptr) return r;
    std::array<char, 4096> buf{};
    size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
    const int status = pclose(pipe);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

// Whether Debian's Python can draw figures (matplotlib and numpy), as polyroll's figure scripts need.
inline bool have_matplotlib() { return run_command("/usr/bin/python3 -c 'import matplotlib, numpy'").exit_code == 0; }

// A file's bytes ("" if it cannot be read).
inline std::string read_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// A results table without its last column, wall_time_s: the one cell that differs between runs
// and hosts, so two tables of the same sweep compare equal without it.
inline std::string table_without_wall_time(const std::string& table) {
    std::istringstream in(table);
    std::string line, out;
    while (std::getline(in, line)) out += line.substr(0, line.rfind(',')) + "\n";
    return out;
}

// A fresh, empty scratch folder (removed first if it exists; created when `create`).
inline std::filesystem::path scratch_dir(const std::string& name, bool create = false) {
    // The process id in the name: two test runs at once on one machine (two builds, a developer
    // beside CI) never share a folder.
    const std::filesystem::path p =
        std::filesystem::temp_directory_path() / ("polyroll-test-" + std::to_string(::getpid()) + "-" + name);
    std::filesystem::remove_all(p);
    if (create) std::filesystem::create_directories(p);
    return p;
}

// One test file's scratch folders: `scratch("x")` is scratch_dir(prefix + "x", create), fresh each time.
class Scratch {
public:
    explicit Scratch(std::string prefix, bool create = false) : prefix_(std::move(prefix)), create_(create) {}
    std::filesystem::path operator()(const std::string& name) const { return scratch_dir(prefix_ + name, create_); }

private:
    std::string prefix_;
    bool create_;
};

// How many lines a command printed.
inline std::size_t line_count(const std::string& out) {
    return static_cast<std::size_t>(std::count(out.begin(), out.end(), '\n'));
}

// Runs `command` and checks it is refused as bad input is: exit 2, one line holding each of `words`,
// and `out` (the folder it was told to write) not created. Returns what it printed, for more checks.
inline CommandResult expect_refused(const std::string& command, const std::vector<std::string>& words,
                                    const std::filesystem::path& out) {
    const CommandResult r = run_command(command);
    INFO(command << "\n" << r.out);
    CHECK(r.exit_code == 2);
    CHECK(line_count(r.out) == 1);
    for (const std::string& w : words) CHECK_THAT(r.out, Catch::Contains(w));
    CHECK_FALSE(std::filesystem::exists(out));
    return r;
}

#ifdef POLYROLL_EXE
// The polyroll program under test.
inline const std::string kPolyrollExe = POLYROLL_EXE;

// `polyroll ARGS`, as a user runs it.
inline CommandResult run_polyroll(const std::string& args) { return run_command(kPolyrollExe + " " + args); }
#endif

#ifdef POLYROLL_SANDBOX_EXE
// The polyroll-sandbox program under test.
inline const std::string kSandboxExe = POLYROLL_SANDBOX_EXE;
#endif

}  // namespace polyroll::test
