// How many cores one run may use by itself: the 3D reference gives Yade that many OpenMP threads
// (yade_process.cpp). A process has the cores its CPU affinity allows (a Slurm task's cpuset), at
// most SLURM_CPUS_PER_TASK where Slurm sets it; a sweep shares them among its jobs, each worker
// thread holding a ScopedRunCores of its share.
#pragma once

namespace polyroll {

// The cores this process may run on (at least 1).
int process_cores();

// This thread's share: the innermost ScopedRunCores, else process_cores().
int run_cores();

// Whether the process runs on cores reserved for it: inside a Slurm allocation (SLURM_CPUS_PER_TASK
// set), rather than on a machine it shares with whatever else runs there.
bool in_allocation();

class ScopedRunCores {
public:
    explicit ScopedRunCores(int cores);
    ~ScopedRunCores();
    ScopedRunCores(const ScopedRunCores&) = delete;
    ScopedRunCores& operator=(const ScopedRunCores&) = delete;

private:
    int previous_;
};

}  // namespace polyroll
