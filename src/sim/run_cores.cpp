// How many cores one run may use: see run_cores.h.
#include "sim/run_cores.h"

#include <algorithm>
#include <cstdlib>

#include <sched.h>

namespace polyroll {

namespace {
thread_local int t_cores = 0;  // 0: no share set on this thread
}  // namespace

int process_cores() {
    int cores = 1;
#if defined(__EMSCRIPTEN__)
    return cores;  // a page runs no 3D reference: one core is all a run asks
#endif
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0) cores = std::max(1, CPU_COUNT(&set));
    // Slurm without a cpuset (TaskPlugin=task/none) leaves the affinity whole: its allocation is the bound.
    if (const char* env = std::getenv("SLURM_CPUS_PER_TASK"); env && *env) {
        char* end = nullptr;
        const long n = std::strtol(env, &end, 10);
        if (end != env && *end == '\0' && n >= 1) cores = std::min<long>(cores, n);
    }
    return cores;
}

bool in_allocation() {
    const char* env = std::getenv("SLURM_CPUS_PER_TASK");
    return env != nullptr && *env != '\0';
}

int run_cores() { return t_cores > 0 ? t_cores : process_cores(); }

ScopedRunCores::ScopedRunCores(int cores) : previous_(t_cores) { t_cores = std::max(1, cores); }

ScopedRunCores::~ScopedRunCores() { t_cores = previous_; }

}  // namespace polyroll
