// polyroll bench, rendering: the time per frame of each stage (simulating to the next frame,
// building the draw list, drawing and reading back, encoding PNGs on the encoder threads) and the
// end-to-end frames per second of a render, with and without PNG output.
#include "cli/bench_render.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <thread>
#include <unistd.h>

#include <fmt/core.h>

#include "render/font.h"
#include "render/frame_builder.h"
#include "render/frame_schedule.h"
#include "render/render_sequence.h"
#include "sim/model_registry.h"
#include "sim/wall_clock.h"

namespace polyroll::cli {

namespace {


// Enough frames to time: the default scene stops after about 1.2 s, so 4x slow motion.
constexpr int kWidth = 1280, kHeight = 720, kSlow = 4;
constexpr double kFps = 30.0;

}  // namespace

void bench_rendering(const Scene& scene, int repeats) {
    render::SequenceSettings st;
    st.frame.width_px = kWidth;
    st.frame.height_px = kHeight;
    st.fps = kFps;
    st.slow = kSlow;
    st.hold_s = 0.0;
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    fmt::print("\nrendering: {}x{}, {:g} fps x {} slow motion, no hold; best of {}; {} cores\n", kWidth, kHeight, kFps,
               kSlow, repeats, cores);

    // The stages alone, on this thread.
    {
        std::unique_ptr<ModelRun> data_run = start_run(scene);
        data_run->run_to_end();
        const RunResult data = data_run->result();
        const render::FrameSchedule sched{kFps, kSlow, scene.fidelity.step_hz, 0.0};
        const long frames = sched.run_frames(data_run->steps());
        const render::FrameOptions options = render::options_for_run(st.frame, data);
        const render::FontAtlas font(render::find_font_dir(), render::frame_fonts(options));
        double best_sim = 1e300, best_list = 1e300;
        for (int rep = 0; rep < repeats; ++rep) {
            const std::unique_ptr<ModelRun> run = start_run(scene);
            double sim_s = 0.0, list_s = 0.0;
            for (long k = 0; k < frames; ++k) {
                auto t0 = WallClock::now();
                while (run->steps() < sched.step_for_frame(k) && run->step()) {
                }
                sim_s += seconds_since(t0);
                t0 = WallClock::now();
                const render::DrawList dl = render::build_frame(run->snapshot(), options, font);
                list_s += seconds_since(t0);
            }
            best_sim = std::min(best_sim, sim_s);
            best_list = std::min(best_list, list_s);
        }
        fmt::print("{:<44} {:>9} {:>10}\n", "stage (per frame, one thread)", "ms/frame", "frames/s");
        fmt::print("{:<44} {:>9.3f} {:>10.0f}\n", "simulate to the next frame", 1e3 * best_sim / frames,
                   frames / best_sim);
        fmt::print("{:<44} {:>9.3f} {:>10.0f}\n", "snapshot and draw list", 1e3 * best_list / frames,
                   frames / best_list);
    }

    // Whole renders, as `polyroll render` runs them.
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / fmt::format("polyroll-bench-{}", ::getpid());
    struct Case {
        const char* name;
        bool png;
        int threads;
    };
    const Case cases[] = {{"render, no PNG (draw + read back)", false, 1},
                          {"render + PNG, 1 encoder thread", true, 1},
                          {"render + PNG, encoder thread per core", true, static_cast<int>(cores)}};
    fmt::print("{:<44} {:>9} {:>10} {:>10}  {}\n", "end to end", "frames", "frames/s", "total_s", "");
    for (const Case& c : cases) {
        double best_loop = 1e300, best_total = 1e300;
        long frames = 0;
        double mb = 0.0;
        for (int rep = 0; rep < repeats; ++rep) {
            std::filesystem::remove_all(dir);
            std::filesystem::create_directories(dir);
            st.write_png = c.png;
            st.encoder_threads = c.threads;
            const auto t0 = WallClock::now();
            const render::SequenceResult r = render::render_sequence(scene, st, dir);
            best_total = std::min(best_total, seconds_since(t0));
            best_loop = std::min(best_loop, r.render_wall_s);
            frames = r.run_frames + r.hold_frames;
            mb = static_cast<double>(r.png_bytes) / 1e6;
        }
        fmt::print("{:<44} {:>9} {:>10.0f} {:>10.3f}  {}\n", c.name, frames, frames / best_total, best_total,
                   c.png ? fmt::format("{:.0f} KB/frame", 1e3 * mb / std::max(1L, frames)) : "");
        std::fflush(stdout);
    }
    std::filesystem::remove_all(dir);
    fmt::print("end to end: from the scene to the last frame on disk, including the data run, the font atlas and\n"
               "the GL context (frames/s = frames / total_s).\n");
}

}  // namespace polyroll::cli
