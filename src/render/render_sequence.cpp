// The headless frame sequence: see render_sequence.h.
#include "render/render_sequence.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <thread>

#include <fmt/core.h>

#include "render/font.h"
#include "render/frame_builder.h"
#include "render/frame_encoder.h"
#include "render/frame_schedule.h"
#include "render/gl_renderer.h"
#include "render/offscreen_osmesa.h"
#include "render/snapshot.h"
#include "render/ticks.h"
#include "render/world_draw.h"
#include "sim/model_registry.h"

namespace polyroll::render {

namespace {

using Clock = std::chrono::steady_clock;

// x rounded up to a multiple of a nice step about a fifth of it: 1.225 -> 1.5, 5.5 -> 6.
double round_up_readable(double x) { return round_up_nice(x, 5.0); }

}  // namespace

FrameOptions options_for_run(FrameOptions o, const RunResult& run) {
    double v_lo = 0.0, v_hi = 0.0;
    for (const TrajectorySample& t : run.measured.trajectory) {
        v_lo = std::min(v_lo, t.speed_m_s);
        v_hi = std::max(v_hi, t.speed_m_s);
    }
    o.plot_time_max_s = std::max(0.5, round_up_readable(run.measured.end_time_s));
    o.plot_speed_max_m_s = std::max(0.05, round_up_readable(v_hi));
    o.plot_speed_min_m_s = -round_up_readable(-v_lo);
    // Grains swing faster than the lid centre (rotation adds to the roll); 1.5x keeps most in range.
    o.colour_speed_max_m_s = std::max(0.05, round_up_readable(1.5 * std::max(v_hi, -v_lo)));
    return o;
}

std::string outcome_text(const Measurements& m) {
    switch (m.behaviour) {
        case Behaviour::stopped_at_first_impact:
            return fmt::format("stopped at its first impact, after {:.2f} m", m.distance_m);
        case Behaviour::stopped: return fmt::format("stopped after {:.2f} m", m.distance_m);
        case Behaviour::rolled_to_end: return fmt::format("rolled to the end ({:.2f} m)", m.distance_m);
        case Behaviour::time_limit: return fmt::format("time limit reached after {:.2f} m", m.distance_m);
        case Behaviour::diverged: return "stopped: the simulation diverged";
        case Behaviour::running: return "";
    }
    return "";
}

SequenceResult render_sequence(const Scene& scene, const SequenceSettings& st, const std::filesystem::path& dir,
                               const std::function<void(const SequenceProgress&)>& progress) {
    SequenceResult result;
    // The data run, as `polyroll run` runs it: the same files.
    const auto data_start = Clock::now();
    long data_steps = 0;  // tracker steps (a reduced model's RunResult counts its integrator's)
    std::unique_ptr<ModelRun> replay;  // the drawn run, where the model can give it without running again
    {
        std::unique_ptr<ModelRun> data_run = start_run(scene);
        data_run->run_to_end();
        data_steps = data_run->steps();
        result.run = data_run->result();
        replay = data_run->replay();
    }
    result.run.wall_time_s = std::chrono::duration<double>(Clock::now() - data_start).count();
    const RunResult& data = result.run;

    const FrameSchedule sched{st.fps, st.slow, scene.fidelity.step_hz, st.hold_s};
    result.run_frames = sched.run_frames(data_steps);
    result.hold_frames = sched.hold_frames();
    const long expected = result.run_frames + result.hold_frames;

    FrameOptions options = options_for_run(st.frame, data);
    options.slow_motion = st.slow;
    const FontAtlas font(find_font_dir(), frame_fonts(options));
    OffscreenContext context(options.width_px, options.height_px);
    GlRenderer gl;
    result.gl_renderer = context.renderer();

    const int threads = st.encoder_threads > 0 ? st.encoder_threads
                                               : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::optional<FrameEncoder> encoder;
    if (st.write_png) encoder.emplace(dir, threads, 2 * threads);
    const size_t frame_bytes = static_cast<size_t>(options.width_px) * static_cast<size_t>(options.height_px) * 4;
    const ImageView format{nullptr, options.width_px, options.height_px, 4, true};
    std::vector<std::uint8_t> scratch;  // read-back target when no PNG is written

    const auto start = Clock::now();
    long done = 0;
    auto emit = [&](const Snapshot& snap, int copies, const FrameOptions& frame_options) {
        gl.draw(build_frame(snap, frame_options, font));
        if (encoder) {
            std::vector<std::uint8_t> pixels = encoder->take_buffer(frame_bytes);
            context.read_rgba_bottom_up(pixels.data());
            encoder->submit(done + 1, copies, format, std::move(pixels));
        } else {
            scratch.resize(frame_bytes);
            context.read_rgba_bottom_up(scratch.data());
        }
        done += copies;
        if (progress) progress({done, expected, std::chrono::duration<double>(Clock::now() - start).count()});
    };

    const std::unique_ptr<ModelRun> run = replay ? std::move(replay) : start_run(scene);
    for (long k = 0; k < result.run_frames; ++k) {
        const long target = sched.step_for_frame(k);
        while (run->steps() < target && run->step()) {
        }
        if (run->steps() != target)
            throw std::logic_error(fmt::format("the render run ended at step {} but the data run went on to step {}: "
                                               "the simulation is not deterministic",
                                               run->steps(), data_steps));
        emit(run->snapshot(), 1, options);
    }
    while (run->step()) {
    }
    if (run->steps() != data_steps)
        throw std::logic_error(fmt::format("the render run ended at step {}, the data run at step {}: the simulation "
                                           "is not deterministic",
                                           run->steps(), data_steps));
    // The final state, held: drawn and encoded once, written as many times as it is shown.
    // The held frames carry the outcome banner: the run's ending said in words.
    if (result.hold_frames > 0) {
        FrameOptions held = options;
        held.outcome = outcome_text(data.measured);
        emit(run->snapshot(), static_cast<int>(result.hold_frames), held);
    }
    if (encoder) {
        encoder->finish();
        result.png_bytes = encoder->bytes_written();
    }
    result.render_wall_s = std::chrono::duration<double>(Clock::now() - start).count();
    if (progress) progress({done, expected, result.render_wall_s});
    return result;
}

}  // namespace polyroll::render
