// A run computed whole before it is shown (the reduced models, the free rigid body, the 3D reference)
// is revealed in the tracker's steps: what has happened by a time, and the first step at which the run
// has ended. Core, because models in different wings reveal their runs the same way.
#pragma once

#include "sim/measurements.h"

namespace polyroll {

// Moves the rows and impacts of `whole` up to `time_s` into `shown`; once `finished`, `shown` is all
// of `whole` (the behaviour, distance and terminal velocity are known only then).
void reveal_up_to(Measurements& shown, const Measurements& whole, double time_s, bool finished);

// The first tracker step, not before `from_step`, at or after `end_time_s`: computed rather than
// counted up to (counting ten thousand steps one by one cost about a third of a segment-model run on
// the default scene). `from_step` if there is no end to jump to.
long first_step_at_end(double end_time_s, double step_hz, long from_step);

}  // namespace polyroll
