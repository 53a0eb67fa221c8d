// The sandbox's physics thread: one worker, alive as long as the window, that waits for a frame's
// requests, runs the physics job on them and hands the outcome back. The requests go in and the
// outcome comes out under its lock; that hand-off is the only thing the two threads share.
#pragma once

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#include "app/physics_requests.h"

namespace polyroll::app {

class PhysicsWorker {
public:
    using Job = std::function<PhysicsOutcome(const PhysicsRequests&)>;

    // Starts the thread, which then waits for requests.
    explicit PhysicsWorker(Job job);
    // Lets a job in hand finish, then ends the thread.
    ~PhysicsWorker();
    PhysicsWorker(const PhysicsWorker&) = delete;
    PhysicsWorker& operator=(const PhysicsWorker&) = delete;

    // Hands over a job's requests and returns at once; one job at a time (std::logic_error if one
    // has not been finished).
    void start(PhysicsRequests requests);
    // Waits for the job and hands back its outcome; rethrows what the job threw.
    PhysicsOutcome finish();
    // Both at once, for a job the caller waits for (a capture's frame, commands at the sync point).
    PhysicsOutcome run(PhysicsRequests requests);

    bool busy() const;  // started and not yet finished

private:
    void loop();
    // The finished job's outcome, or what it threw, once: the worker is free again (the desktop's
    // worker calls it under its lock).
    PhysicsOutcome hand_back();

    Job job_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;  // the worker waits here for requests or the end
    std::condition_variable done_;  // the caller waits here for the outcome
    std::optional<PhysicsRequests> requests_;
    std::optional<PhysicsOutcome> outcome_;
    std::exception_ptr error_;
    bool busy_ = false;
    [[maybe_unused]] bool stop_ = false;  // the thread's end: unused by the page's inline worker (src/web/)
    std::thread thread_;  // last: started once everything it uses exists
};

// The parts the desktop's threaded worker (physics_worker.cpp) and the page's inline one
// (src/web/physics_worker_inline.cpp) share.
inline PhysicsOutcome PhysicsWorker::run(PhysicsRequests requests) {
    start(std::move(requests));
    return finish();
}

inline PhysicsOutcome PhysicsWorker::hand_back() {
    busy_ = false;
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
    const PhysicsOutcome out = *outcome_;
    outcome_.reset();
    return out;
}

}  // namespace polyroll::app
