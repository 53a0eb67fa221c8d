// Running the 3D reference's script (polyroll_dem3d.py) in Yade, as a subprocess: Yade found on the
// PATH (or $POLYROLL_YADE) and imported as a library by its own Python, on one thread unless a Slurm
// allocation reserves cores for the run (threads()), its progress read as it comes, stopped by a
// timeout, and never outliving polyroll (Ctrl-C or a crash of polyroll ends it too).
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace polyroll::dem3d {

// Yade's command, or throws InputError saying how to install it (the CLI exits with 2).
std::string yade_command();

// The script's path: $POLYROLL_DEM3D_DIR, then <exe>/../share/polyroll/dem3d, then the source tree.
std::string script_path();

// The longest a run may take in wall-clock seconds before it is stopped: $POLYROLL_DEM3D_TIMEOUT_S,
// else 2 hours (a whole-ramp run of the octagon takes about two minutes).
double timeout_s();

// The OpenMP threads Yade runs with for a run started on this thread: $POLYROLL_DEM3D_THREADS (1 to
// 64; InputError otherwise), else inside a Slurm allocation the cores the run has there
// (sim/run_cores.h: a run alone has the task's, a sweep's run its share of them), else one.
// docs/physics.md ("Yade's threads") has the measured speed-up, and why a run's numbers depend on
// its thread count.
int threads();

// Writes `input` as IN.json into `dir` (an existing folder) and runs the script on it there with
// threads() threads, which it returns. Throws std::runtime_error with Yade's last words if it fails
// or times out, RunStopped if this thread's stop hook asked (sim/run_progress.h), where Yade's
// progress lines go too.
int run_script(const nlohmann::ordered_json& input, const std::filesystem::path& dir);

}  // namespace polyroll::dem3d
