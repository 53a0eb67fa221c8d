// The live readouts of a lane as text, in SI units: time, position, speed, face impacts, the
// behaviour once known, distance and terminal velocity. Plain strings, so the panel only lays
// them out and the tests read them.
#pragma once

#include <string>

#include "sim/measurements.h"
#include "sim/scene.h"

namespace polyroll::app {

struct LaneReadout {
    std::string title;      // "n = 6, r = 0.4 BBs"
    std::string polygon;    // "n = 6"
    std::string fill;       // "empty", "0.4 BBs"
    std::string time;       // "1.23 s"
    std::string position;   // "0.456 m"
    std::string speed;      // "0.12 m/s"
    std::string impacts;    // "7"
    std::string behaviour;  // "rolling", "stopped", ...
    std::string distance;   // "-" until known
    std::string terminal;   // "-" unless it rolled to the end
};

// How the panel names a behaviour ("stopped at 1st impact", "rolled to the end", ...).
std::string behaviour_label(Behaviour b);

LaneReadout lane_readout(const Scene& scene, const Measurements& m, double time_s);

}  // namespace polyroll::app
