// The calibration's part of polyroll bench: the measured cost of one evaluation (every run of the
// bundled observations at one seed) and what a three-parameter calibration at that cost takes.
#pragma once

namespace polyroll::cli {

// Runs the bundled observations' plan once, one seed, one run at a time on one core, at `fidelity`.
void bench_calibration(const char* fidelity);

}  // namespace polyroll::cli
