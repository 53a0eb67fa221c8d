// How far a long run has got, for a person waiting at a terminal. A model whose runs take minutes
// (ModelTraits::reports_progress: the 3D reference) calls the hook about every quarter simulated
// second; the others never do. The hook belongs to the thread that starts the run, so a sweep's many
// runs on their own threads stay silent unless one of them asks.
#pragma once

#include <functional>

namespace polyroll {

// Called with the simulated time and the distance rolled so far.
using RunProgress = std::function<void(double time_s, double distance_m)>;

// Where progress goes for runs started on this thread until the scope ends (the previous hook is put
// back then).
class ScopedRunProgress {
public:
    explicit ScopedRunProgress(RunProgress hook);
    ~ScopedRunProgress();
    ScopedRunProgress(const ScopedRunProgress&) = delete;
    ScopedRunProgress& operator=(const ScopedRunProgress&) = delete;

private:
    RunProgress previous_;
};

// Tells this thread's hook, if there is one.
void report_run_progress(double time_s, double distance_m);

}  // namespace polyroll
