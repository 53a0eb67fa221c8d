// The no-display fallback: see headless_fallback.h.
#include "app/headless_fallback.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include <fmt/core.h>

#include "process/child_process.h"
#include "sim/files/atomic_file.h"

namespace polyroll::app {

namespace fs = std::filesystem;

std::string sibling_polyroll() { return process::sibling_executable("polyroll"); }

namespace {

bool free_for_a_render(const fs::path& p) {
    std::error_code ec;
    if (!fs::exists(p, ec)) return true;
    if (!fs::is_directory(p, ec)) return false;
    return fs::is_empty(p, ec) || fs::is_regular_file(p / kFallbackMarker, ec);
}

// The folder `wanted` names, as a path with a last component: "runs/default/" is "runs/default", and
// "." the current folder by its own name (a sibling needs one).
fs::path named_folder(const fs::path& wanted) {
    fs::path base = wanted.lexically_normal();
    if (!base.has_filename()) base = base.parent_path();
    if (base.empty() || base.filename() == "." || base.filename() == "..") {
        base = fs::absolute(base).lexically_normal();
        if (!base.has_filename()) base = base.parent_path();
    }
    return base;
}

}  // namespace

// This fallback is what the README's main command does on a machine without a display, so running
// it again must work (a refusal would fail the second try with exit 2, and the sandbox has no
// --force to offer) without adding another 60 MB of the same frames each time: it replaces its own
// earlier render, which its marker names. A folder it did not write (no marker) is never touched:
// the render goes to the next numbered one.
fs::path fresh_render_folder(const fs::path& wanted) {
    fs::path base = named_folder(wanted);  // not const: returned by move
    if (free_for_a_render(base)) return base;
    for (int k = 2;; ++k) {
        fs::path p = base;
        p.replace_filename(fmt::format("{}-{}", base.filename().string(), k));
        if (free_for_a_render(p)) return p;
    }
}

int run_headless_instead(const std::string& why, const std::string& out, const HeadlessScene& scene) {
    const std::string exe = sibling_polyroll();
    const fs::path folder = fresh_render_folder(out);
    const fs::path scene_file = folder / kHeadlessSceneFile;
    const std::string kept =
        folder == named_folder(out) ? "" : fmt::format("; {} is not this fallback's and is left as it is", out);
    const std::string scene_flag = scene.scene_json.empty() ? "" : " --scene " + scene_file.string();
    std::error_code ec;
    const bool replacing = fs::is_regular_file(folder / kFallbackMarker, ec);
    fmt::print("polyroll-sandbox: no display ({}): rendering {} headless instead (polyroll render --out {}{}{}{})\n",
               why, scene.what, folder.string(), scene_flag,
               replacing ? ", replacing this fallback's earlier frames there" : "", kept);
    std::fflush(stdout);
    std::fflush(stderr);
    // The marker first, so the folder is known as this fallback's even if the render is stopped;
    // --force because the folder then holds the marker (and, replacing, the earlier frames).
    fs::create_directories(folder, ec);
    if (FILE* f = std::fopen((folder / kFallbackMarker).c_str(), "w")) {
        std::fputs("Written by polyroll-sandbox without a display: its next run without one replaces this "
                   "folder's frames.\n",
                   f);
        std::fclose(f);
    }
    std::vector<std::string> args{exe, "render", "--out", folder.string(), "--force"};
    if (!scene.scene_json.empty()) {
        // Beside the frames, so the render can be made again (or the scene read) from the folder.
        write_file_atomic(scene_file, scene.scene_json);
        args.insert(args.end(), {"--scene", scene_file.string()});
    } else {
        fs::remove(scene_file, ec);  // an earlier chosen scene's file would name frames it no longer drew
    }
    process::replace_process(args);
    fmt::print(stderr, "polyroll-sandbox: could not run {}: {}\n", exe, std::strerror(errno));
    return 1;
}

}  // namespace polyroll::app
