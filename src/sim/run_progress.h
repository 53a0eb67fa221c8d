// How far a long run has got, for a person waiting at a terminal, and whether the caller wants it
// stopped. A model whose runs take minutes (ModelTraits::reports_progress: the 3D reference) calls the
// progress hook about every quarter simulated second; the others never do. The stop hook is asked
// between the steps of ModelRun::run_to_end, and by the 3D reference about every 0.2 s of wall time
// while its subprocess works. The hooks belong to the thread that starts the run, so a sweep's many
// runs on their own threads stay silent and unstopped unless one of them asks.
#pragma once

#include <functional>
#include <stdexcept>

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

// Whether the run should stop now (the Python module's hook: a Ctrl-C arrived).
using RunStopCheck = std::function<bool()>;

// The stop hook for runs started on this thread until the scope ends (the previous one put back then).
class ScopedRunStop {
public:
    explicit ScopedRunStop(RunStopCheck check);
    ~ScopedRunStop();
    ScopedRunStop(const ScopedRunStop&) = delete;
    ScopedRunStop& operator=(const ScopedRunStop&) = delete;

private:
    RunStopCheck previous_;
};

// Asks this thread's stop hook; false without one.
bool run_stop_requested();
// Whether this thread has a stop hook (a model then polls it).
bool run_stop_hooked();

// Thrown by a run stopped at its caller's request: nothing of it is kept.
struct RunStopped : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace polyroll
