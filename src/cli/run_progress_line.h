// What `polyroll run` prints while a slow model (the 3D reference, minutes a run) runs: the simulated
// time, the distance and faces rolled, and the wall time left at the pace so far. On a terminal one
// line rewritten in place at every report; into a file or a notebook a whole line every 15 s of
// wall time, so a log is never silent for long and never fills with carriage returns.
#pragma once

#include <string>

#include "sim/scene/scene.h"
#include "sim/wall_clock.h"

namespace polyroll::cli {

class RunProgressLine {
public:
    RunProgressLine(const Scene& scene, bool terminal);
    // A report from the run: `time_s` simulated, the lid centre `distance_m` down the ramp.
    void report(double time_s, double distance_m);
    // Clears the terminal's line (nothing to clear in a file).
    void finish();
    // The text of a report at `wall_s` seconds of wall time since the run began (for the tests).
    std::string text(double time_s, double distance_m, double wall_s) const;

private:
    std::string model_;
    double time_limit_s_ = 0.0;
    double track_m_ = 0.0;   // from the release to where the run ends
    double side_m_ = 0.0;    // one face: the distance a roll over one vertex moves the centre
    bool terminal_ = false;
    WallClock::time_point start_;
    double last_line_wall_s_ = 0.0;
};

}  // namespace polyroll::cli
