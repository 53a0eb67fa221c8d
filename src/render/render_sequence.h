// Renders a scene headless to a PNG frame sequence, whatever its model: a data run first (the results files and the
// exact frame count, so the progress and the plot's axes are known from the first frame), then the
// same run again, deterministic, stepped frame by frame while an OSMesa context draws each frame
// and a pool of encoder threads writes the PNGs (frame_encoder.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "render/frame_layout.h"
#include "sim/run_result.h"
#include "sim/scene/scene.h"

namespace polyroll::render {

struct SequenceSettings {
    FrameOptions frame;     // size, camera, grain colours (the plot axes are set from the data run)
    double fps = 30.0;
    int slow = 1;           // frames per simulated second = fps x slow
    double hold_s = 1.0;    // the final state stays on screen this long (seconds of video)
    bool write_png = true;  // false: draw and read back only (to time the renderer alone)
    int encoder_threads = 0;  // 0: one per core
};

struct SequenceProgress {
    long frames_done = 0;
    long frames_expected = 0;
    double wall_s = 0.0;  // since rendering began (after the data run)
};

struct SequenceResult {
    RunResult run;            // the data run, as `polyroll run` gives it (a race: its first lane's)
    std::vector<RunResult> lane_runs;  // every lane's data run (one for render_sequence)
    long run_frames = 0;      // frames of the moving run
    long hold_frames = 0;     // copies of the final state after it
    std::uint64_t png_bytes = 0;
    double render_wall_s = 0.0;  // simulating, drawing and writing the frames
    std::string gl_renderer;
};

// Frames go to dir/frame_000001.png ... (dir must exist). Throws InputError for a scene it cannot
// run and std::runtime_error for a failure to render or write.
SequenceResult render_sequence(const Scene& scene, const SequenceSettings& settings, const std::filesystem::path& dir,
                               const std::function<void(const SequenceProgress&)>& progress = {});

// A race: every lane's run drawn side by side in each frame, as the window shows them
// (race_frame.h); the frames follow simulated time, a lane that has ended stays as it ended, and the
// sequence runs until the last lane has ended. Throws as render_sequence.
SequenceResult render_race(const std::vector<Scene>& lanes, const SequenceSettings& settings,
                           const std::filesystem::path& dir,
                           const std::function<void(const SequenceProgress&)>& progress = {});

// The frame options for a run whose results are known: the plot's axes cover the whole run and
// the speed colour map tops out a little above the fastest speed, both rounded to readable values.
// The outcome banner's words for a finished run: "stopped after 0.14 m", "rolled to the end (2.50 m)".
std::string outcome_text(const Measurements& m);

FrameOptions options_for_run(FrameOptions base, const RunResult& run);

}  // namespace polyroll::render
