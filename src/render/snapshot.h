// A snapshot: the state of a run at one instant in SI units, all a frame needs. It is built by the run
// itself, whatever the model (sim/run_snapshot.h, ModelRun::snapshot); render keeps its own names.
#pragma once

#include "sim/run_snapshot.h"

namespace polyroll::render {

using GrainState = polyroll::GrainState;
using SpeedPoint = polyroll::SpeedPoint;
using Snapshot = polyroll::RunSnapshot;

}  // namespace polyroll::render
