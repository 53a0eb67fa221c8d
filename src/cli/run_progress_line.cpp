// The progress line of a slow run: see run_progress_line.h.
#include "cli/run_progress_line.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <fmt/core.h>

#include "sim/geometry/shell_pose.h"
#include "sim/geometry/shell_properties.h"
#include "sim/scene/scene_names.h"

namespace polyroll::cli {

namespace {
constexpr double kFileLineEveryS = 15.0;  // wall seconds between the lines written to a file
}

RunProgressLine::RunProgressLine(const Scene& scene, bool terminal)
    : model_(to_string(scene.run.model)), time_limit_s_(scene.run.time_limit_s), terminal_(terminal),
      start_(WallClock::now()) {
    const ShellProperties shell = shell_properties(scene.shell);
    side_m_ = shell.outer_side_m;
    track_m_ = std::max(0.0, end_centre_x_m(scene, shell) - release_pose(scene, shell).centre_m.x);
}

std::string RunProgressLine::text(double time_s, double distance_m, double wall_s) const {
    const int faces = side_m_ > 0.0 ? static_cast<int>(std::floor(std::max(0.0, distance_m) / side_m_ + 1e-9)) : 0;
    std::string line = fmt::format("{}: {:.2f} of at most {:g} s simulated, {:.3f} of {:.2f} m rolled ({} {})", model_,
                                   time_s, time_limit_s_, distance_m, track_m_, faces, faces == 1 ? "face" : "faces");
    // The time left at the pace so far: the wall time a simulated second costs, times what is left of
    // the track at the mean speed so far, or of the time limit if that comes first. A run that stops
    // takes less.
    if (time_s > 0.0 && wall_s > 0.0) {
        const double mean_speed_m_s = distance_m / time_s;
        double left_sim_s = time_limit_s_ - time_s;
        if (mean_speed_m_s > 0.0) left_sim_s = std::min(left_sim_s, (track_m_ - distance_m) / mean_speed_m_s);
        const double left_wall_s = std::max(0.0, left_sim_s) * wall_s / time_s;
        line += fmt::format(", at most about {:.0f} s left", left_wall_s);
    }
    return line;
}

void RunProgressLine::report(double time_s, double distance_m) {
    const double wall_s = seconds_since(start_);
    if (terminal_) {
        fmt::print(stderr, "\r  {}   ", text(time_s, distance_m, wall_s));
    } else {
        if (wall_s - last_line_wall_s_ < kFileLineEveryS) return;
        last_line_wall_s_ = wall_s;
        fmt::print(stderr, "  {}\n", text(time_s, distance_m, wall_s));
    }
    std::fflush(stderr);
}

void RunProgressLine::finish() {
    if (terminal_) fmt::print(stderr, "\r{:120}\r", "");
}

}  // namespace polyroll::cli
