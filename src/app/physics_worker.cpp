// The sandbox's persistent physics thread: see physics_worker.h.
#include "app/physics_worker.h"

#include <stdexcept>
#include <utility>

namespace polyroll::app {

PhysicsWorker::PhysicsWorker(Job job) : job_(std::move(job)), thread_([this] { loop(); }) {}

PhysicsWorker::~PhysicsWorker() {
    {
        const std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_one();
    thread_.join();
}

void PhysicsWorker::start(PhysicsRequests requests) {
    {
        const std::lock_guard lock(mutex_);
        if (busy_) throw std::logic_error("PhysicsWorker::start: the previous job has not been finished");
        requests_ = std::move(requests);
        outcome_.reset();
        error_ = nullptr;
        busy_ = true;
    }
    wake_.notify_one();
}

PhysicsOutcome PhysicsWorker::finish() {
    std::unique_lock lock(mutex_);
    if (!busy_) throw std::logic_error("PhysicsWorker::finish: no job was started");
    done_.wait(lock, [this] { return outcome_.has_value() || error_; });
    return hand_back();
}

bool PhysicsWorker::busy() const {
    const std::lock_guard lock(mutex_);
    return busy_;
}

void PhysicsWorker::loop() {
    std::unique_lock lock(mutex_);
    for (;;) {
        // A job handed over before the end is still run: its caller may be waiting for it.
        wake_.wait(lock, [this] { return requests_.has_value() || stop_; });
        if (!requests_) return;
        const PhysicsRequests requests = std::move(*requests_);
        requests_.reset();
        lock.unlock();
        std::optional<PhysicsOutcome> out;
        std::exception_ptr error;
        try {
            out = job_(requests);
        } catch (...) {
            error = std::current_exception();
        }
        lock.lock();
        outcome_ = out;
        error_ = error;
        done_.notify_one();
    }
}

}  // namespace polyroll::app
