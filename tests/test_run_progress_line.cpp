// The progress line of a slow run (cli/run_progress_line.h): what it says, and the time left.
#include <catch2/catch.hpp>

#include <string>

#include <fmt/core.h>

#include "cli/run_progress_line.h"
#include "test_helpers.h"

using namespace polyroll;

TEST_CASE("a slow run's progress names the simulated time, the distance, the faces and the time left", "[cli][progress]") {
    const Scene scene = test::scene_with({{"run", {{"model", "dem3d"}, {"time_limit_s", 30}}}});
    const cli::RunProgressLine line(scene, false);
    // The small hexagon's outer side is 3.6 cm: 0.5 m is 13 whole faces.
    const std::string t = line.text(2.0, 0.5, 40.0);
    INFO(t);
    CHECK(t.rfind("dem3d: 2.00 of at most 30 s simulated, 0.500 of ", 0) == 0);
    CHECK(t.find("m rolled (13 faces)") != std::string::npos);
    // 20 wall seconds a simulated second; the mean speed 0.25 m/s leaves (track - 0.5) / 0.25 s of the
    // roll, under the 28 s the limit leaves.
    const double track_m = std::stod(t.substr(t.find(" of ", t.find("0.500")) + 4));
    const double left_s = (track_m - 0.5) / 0.25 * 20.0;
    CHECK(t.find(fmt::format("at most about {:.0f} s left", left_s)) != std::string::npos);
    // Not moving yet: the time limit bounds what is left.
    CHECK(line.text(1.0, 0.0, 10.0).find("(0 faces), at most about 290 s left") != std::string::npos);
    // Nothing simulated yet: no estimate.
    CHECK(line.text(0.0, 0.0, 0.0).find("left") == std::string::npos);
}
