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
#include "render/race_frame.h"
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

namespace {

// The lanes' frame options: each lane's (options_for_run), the plot's axes and the colour map wide
// enough for all of them.
FrameOptions options_for_runs(const FrameOptions& base, const std::vector<RunResult>& runs) {
    FrameOptions o = options_for_run(base, runs.front());
    for (size_t i = 1; i < runs.size(); ++i) {
        const FrameOptions l = options_for_run(base, runs[i]);
        o.plot_time_max_s = std::max(*o.plot_time_max_s, *l.plot_time_max_s);
        o.plot_speed_max_m_s = std::max(*o.plot_speed_max_m_s, *l.plot_speed_max_m_s);
        o.plot_speed_min_m_s = std::min(*o.plot_speed_min_m_s, *l.plot_speed_min_m_s);
        o.colour_speed_max_m_s = std::max(o.colour_speed_max_m_s, l.colour_speed_max_m_s);
    }
    return o;
}

// One run per lane, drawn together: every lane's data run first, then the same runs again stepped to
// each frame's simulated time (a lane that has ended stays as it ended) and drawn by `frame`.
using BuildFrame = std::function<DrawList(const std::vector<Snapshot>&, const FrameOptions&,
                                          const std::vector<std::string>& outcomes, const FontAtlas&)>;

SequenceResult render_lanes(const std::vector<Scene>& scenes, const SequenceSettings& st,
                            const std::filesystem::path& dir, const std::function<void(const SequenceProgress&)>& progress,
                            const std::vector<FontSpec>& fonts, const BuildFrame& frame) {
    SequenceResult result;
    const size_t n = scenes.size();
    // The data runs, as `polyroll run` runs them: the same files.
    std::vector<long> data_steps(n, 0);  // tracker steps (a reduced model's RunResult counts its integrator's)
    std::vector<std::unique_ptr<ModelRun>> replays(n);  // the drawn runs, where the model can give them without running again
    for (size_t i = 0; i < n; ++i) {
        const auto data_start = Clock::now();
        std::unique_ptr<ModelRun> data_run = start_run(scenes[i]);
        data_run->run_to_end();
        data_steps[i] = data_run->steps();
        result.lane_runs.push_back(data_run->result());
        replays[i] = data_run->replay();
        result.lane_runs.back().wall_time_s = std::chrono::duration<double>(Clock::now() - data_start).count();
    }
    result.run = result.lane_runs.front();

    std::vector<FrameSchedule> sched;
    for (size_t i = 0; i < n; ++i) {
        sched.push_back({st.fps, st.slow, scenes[i].fidelity.step_hz, st.hold_s});
        result.run_frames = std::max(result.run_frames, sched[i].run_frames(data_steps[i]));
    }
    result.hold_frames = sched.front().hold_frames();
    const long expected = result.run_frames + result.hold_frames;

    FrameOptions options = options_for_runs(st.frame, result.lane_runs);
    options.slow_motion = st.slow;
    const FontAtlas font(find_font_dir(), fonts);
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

    std::vector<std::unique_ptr<ModelRun>> runs(n);
    for (size_t i = 0; i < n; ++i) runs[i] = replays[i] ? std::move(replays[i]) : start_run(scenes[i]);
    const auto snapshots = [&runs] {
        std::vector<Snapshot> snaps;
        snaps.reserve(runs.size());
        for (const auto& r : runs) snaps.push_back(r->snapshot());
        return snaps;
    };

    const auto start = Clock::now();
    long done = 0;
    auto emit = [&](int copies, const FrameOptions& frame_options, const std::vector<std::string>& outcomes) {
        gl.draw(frame(snapshots(), frame_options, outcomes, font));
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

    for (long k = 0; k < result.run_frames; ++k) {
        for (size_t i = 0; i < n; ++i) {
            const long target = std::min(sched[i].step_for_frame(k), data_steps[i]);
            ModelRun& run = *runs[i];
            while (run.steps() < target && run.step()) {
            }
            if (run.steps() != target)
                throw std::logic_error(fmt::format("the render run ended at step {} but the data run went on to step {}: "
                                                   "the simulation is not deterministic",
                                                   run.steps(), data_steps[i]));
        }
        emit(1, options, {});
    }
    for (size_t i = 0; i < n; ++i) {
        ModelRun& run = *runs[i];
        while (run.step()) {
        }
        if (run.steps() != data_steps[i])
            throw std::logic_error(fmt::format("the render run ended at step {}, the data run at step {}: the "
                                               "simulation is not deterministic",
                                               run.steps(), data_steps[i]));
    }
    // The final state, held: drawn and encoded once, written as many times as it is shown.
    // The held frames carry the outcome banner: the run's ending said in words.
    if (result.hold_frames > 0) {
        std::vector<std::string> outcomes;
        for (const RunResult& r : result.lane_runs) outcomes.push_back(race_outcome_text(r.measured.behaviour));
        FrameOptions held = options;
        held.outcome = outcome_text(result.run.measured);
        emit(static_cast<int>(result.hold_frames), held, outcomes);
    }
    if (encoder) {
        encoder->finish();
        result.png_bytes = encoder->bytes_written();
    }
    result.render_wall_s = std::chrono::duration<double>(Clock::now() - start).count();
    if (progress) progress({done, expected, result.render_wall_s});
    return result;
}

}  // namespace

SequenceResult render_sequence(const Scene& scene, const SequenceSettings& st, const std::filesystem::path& dir,
                               const std::function<void(const SequenceProgress&)>& progress) {
    return render_lanes({scene}, st, dir, progress, frame_fonts(st.frame),
                        [](const std::vector<Snapshot>& snaps, const FrameOptions& o, const std::vector<std::string>&,
                           const FontAtlas& font) { return build_frame(snaps.front(), o, font); });
}

SequenceResult render_race(const std::vector<Scene>& lanes, const SequenceSettings& st,
                           const std::filesystem::path& dir,
                           const std::function<void(const SequenceProgress&)>& progress) {
    if (lanes.empty()) throw std::invalid_argument("render_race: no lanes");
    return render_lanes(lanes, st, dir, progress, race_frame_fonts(st.frame),
                        [](const std::vector<Snapshot>& snaps, const FrameOptions& o,
                           const std::vector<std::string>& outcomes,
                           const FontAtlas& font) { return build_race_frame(snaps, o, outcomes, font); });
}

}  // namespace polyroll::render
