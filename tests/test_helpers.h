// Shared helpers for the tests: scenes from the bundled defaults with a few fields changed.
#pragma once

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/errors.h"
#include "sim/model_registry.h"
#include "sim/scene.h"
#include "sim/scene_json.h"
#include "sim/simulation.h"

namespace polyroll::test {

// The default scene with `overrides` (a scene document) on top, resolved and validated.
inline Scene scene_with(const nlohmann::ordered_json& overrides) {
    return resolve_scene({SceneLayer{overrides, "test", {}}});
}

// The message a scene document (JSON text) is refused with; "" if it resolves.
inline std::string scene_error_of(const std::string& doc) {
    try {
        scene_with(nlohmann::ordered_json::parse(doc));
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
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
    const std::filesystem::path p = std::filesystem::temp_directory_path() / ("polyroll-test-" + name);
    std::filesystem::remove_all(p);
    if (create) std::filesystem::create_directories(p);
    return p;
}

}  // namespace polyroll::test
