// The sandbox's physics "worker" on the page, which has no threads: start() runs the job at once on
// the main loop (within the frame's physics budget, as on the desktop) and finish() hands back its
// outcome, so the sandbox's loop is the same code on both. The class is physics_worker.h's; the
// desktop's physics_worker.cpp runs the same jobs on a thread instead. The thread and lock members
// stay unused here.
#include "app/physics_worker.h"

#include <stdexcept>
#include <utility>

namespace polyroll::app {

PhysicsWorker::PhysicsWorker(Job job) : job_(std::move(job)) {}

PhysicsWorker::~PhysicsWorker() = default;

void PhysicsWorker::start(PhysicsRequests requests) {
    if (busy_) throw std::logic_error("PhysicsWorker::start: the previous job has not been finished");
    busy_ = true;
    outcome_.reset();
    error_ = nullptr;
    try {
        outcome_ = job_(requests);
    } catch (...) {
        error_ = std::current_exception();
    }
}

PhysicsOutcome PhysicsWorker::finish() {
    if (!busy_) throw std::logic_error("PhysicsWorker::finish: no job was started");
    return hand_back();
}

bool PhysicsWorker::busy() const { return busy_; }

void PhysicsWorker::loop() {}

}  // namespace polyroll::app
