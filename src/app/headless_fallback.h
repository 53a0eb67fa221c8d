// Without a display the sandbox still shows its scene (the default one, or the one its flags chose):
// it says so in one line and hands over to the sibling polyroll executable's headless render, whose
// own output says where the frames went.
#pragma once

#include <filesystem>
#include <string>

namespace polyroll::app {

// Where the headless render goes when neither the user nor the window named a folder.
inline constexpr const char* kHeadlessOutDir = "runs/default";

// The polyroll executable beside this one (the folder of /proc/self/exe).
std::string sibling_polyroll();

// The file that marks a folder as this fallback's own render: the next fallback render replaces that
// folder's frames (rerunning the main command must not add 60 MB each time), and no other folder.
inline constexpr const char* kFallbackMarker = ".polyroll-sandbox-fallback";

// The folder the render writes into: the first of `wanted`, wanted-2, wanted-3, ... that does not
// exist, is empty, or holds this fallback's marker (its own earlier render). Never a folder another
// program or the user wrote.
std::filesystem::path fresh_render_folder(const std::filesystem::path& wanted);

// What the render shows: the default scene, or the one the sandbox's flags chose (--preset, --scene,
// --sides, ...), which it writes beside the frames as kHeadlessSceneFile and renders from there.
struct HeadlessScene {
    std::string what = "the default scene (assets/defaults.json: the paper's Fig. 7 hexagon a quarter full of BBs at 20 deg)";  // for the line, e.g. "the chosen scene (preset octagon-rice)"
    std::string scene_json;                  // the resolved scene as a scene file; "" for the default scene
};
inline constexpr const char* kHeadlessSceneFile = "sandbox-scene.json";

// Prints the line, marks the folder, then replaces this process with `polyroll render --out DIR
// --force` (and `--scene DIR/sandbox-scene.json` for a chosen scene), DIR the fresh_render_folder of
// `out` (the sandbox's --out, or kHeadlessOutDir). Returns only if that could not start (the exit code
// to use).
int run_headless_instead(const std::string& why, const std::string& out, const HeadlessScene& scene = {});

}  // namespace polyroll::app
