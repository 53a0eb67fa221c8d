// The sandbox's physics hand-off without a window: the persistent physics worker (jobs in order on
// one thread, outcomes handed back, errors rethrown, a clean end) and the physics side applying the
// UI's requests (restart, play and pause, step, run to the end, a lane found not finite).
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "app/physics_worker.h"
#include "app/sandbox_physics.h"
#include "app/sandbox_settings.h"
#include "test_helpers.h"

using namespace polyroll;
using namespace polyroll::app;
using json = nlohmann::ordered_json;

namespace {

// A frame's requests numbered by their wall time, so a job can tell which one it was given.
PhysicsRequests frame(double id) {
    PhysicsRequests r;
    r.frame = PhysicsRequests::Frame{id, 1};
    return r;
}

// A wall clock that never moves: no budget ever runs out, so the step counts are exact.
double frozen_clock() { return 0.0; }

// A scene whose lane builds and plays back at once (a reduced model).
Scene quick_scene() { return test::scene_with(json::parse(R"({"fill": {"ratio": 0.4}, "run": {"model": "rigid"}})")); }

PhysicsRequests restart_and_wait(bool play) {
    PhysicsRequests r;
    r.restart_with = std::vector<Scene>{quick_scene()};
    r.wait_until_built = true;
    r.play = play;
    return r;
}

}  // namespace

TEST_CASE("the physics worker runs jobs in order on one thread and hands back their outcomes", "[app][physics]") {
    std::vector<double> seen;  // written only by the worker, read here after each finish
    std::set<std::thread::id> threads;
    PhysicsWorker worker([&](const PhysicsRequests& r) {
        seen.push_back(r.frame ? r.frame->wall_dt_s : -1.0);
        threads.insert(std::this_thread::get_id());
        PhysicsOutcome out;
        out.steps = static_cast<long>(seen.size());
        out.time_s = r.frame ? 10 * r.frame->wall_dt_s : -1.0;
        return out;
    });
    CHECK(!worker.busy());
    for (int i = 1; i <= 20; ++i) {
        worker.start(frame(i));
        CHECK(worker.busy());
        CHECK_THROWS_AS(worker.start(frame(99)), std::logic_error);  // one job at a time
        const PhysicsOutcome out = worker.finish();
        CHECK(!worker.busy());
        CHECK(out.steps == i);
        CHECK(out.time_s == Approx(10.0 * i));
    }
    CHECK(worker.run(PhysicsRequests{}).time_s == -1.0);  // commands alone: no frame
    REQUIRE(seen.size() == 21);
    for (int i = 0; i < 20; ++i) CHECK(seen[static_cast<size_t>(i)] == i + 1);
    // One persistent thread, not the caller's and not a new one per job.
    REQUIRE(threads.size() == 1);
    CHECK(*threads.begin() != std::this_thread::get_id());
    CHECK_THROWS_AS(worker.finish(), std::logic_error);  // nothing started
}

TEST_CASE("the physics worker rethrows a job's error and finishes a job in hand when it ends", "[app][physics]") {
    SECTION("an error reaches the caller, and the worker goes on") {
        PhysicsWorker worker([](const PhysicsRequests& r) {
            if (r.step) throw std::runtime_error("the physics failed");
            return PhysicsOutcome{};
        });
        PhysicsRequests bad;
        bad.step = true;
        worker.start(bad);
        CHECK_THROWS_WITH(worker.finish(), "the physics failed");
        CHECK(!worker.busy());
        CHECK_NOTHROW(worker.run(frame(1)));
    }
    SECTION("ending the worker with a job started lets the job finish first") {
        std::atomic<bool> ran{false};
        {
            PhysicsWorker worker([&](const PhysicsRequests&) {
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
                ran = true;
                return PhysicsOutcome{};
            });
            worker.start(frame(1));
        }  // the destructor joins the thread
        CHECK(ran);
    }
    SECTION("a worker never given a job ends at once") {
        const auto t0 = std::chrono::steady_clock::now();
        { PhysicsWorker worker([](const PhysicsRequests&) { return PhysicsOutcome{}; }); }
        CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(5));
    }
}

TEST_CASE("the sandbox's physics applies the UI's requests and reports what it did", "[app][physics]") {
    SandboxPhysics physics(true, frozen_clock);  // capture frames: a fixed 1/60 s each, no budget

    // Restart with a scene, wait for it, start paused: nothing moves while paused.
    PhysicsOutcome out = physics.run(restart_and_wait(false));
    CHECK(out.built);
    CHECK(!out.build_failed);
    CHECK(!out.playing);
    CHECK(out.time_s == 0.0);
    REQUIRE(physics.lanes().ready());
    out = physics.run(frame(0.0));
    CHECK(out.steps == 0);
    CHECK(out.time_s == 0.0);

    // Play: each frame advances 1/60 s (17 steps at 1000 steps/s, rounded to the step).
    PhysicsRequests play = frame(0.0);
    play.play = true;
    out = physics.run(play);
    CHECK(out.playing);
    CHECK(out.steps > 0);
    CHECK(out.time_s == Approx(kCaptureFrameDtS).margin(1e-3));
    out = physics.run(frame(0.0));
    CHECK(out.time_s == Approx(2 * kCaptureFrameDtS).margin(1e-3));

    // Step: pauses, then advances kSingleStepS at once; the following frames stand still.
    PhysicsRequests step;
    step.step = true;
    const double before_s = out.time_s;
    out = physics.run(step);
    CHECK(!out.playing);
    CHECK(out.time_s == Approx(before_s + kSingleStepS).margin(1e-3));
    CHECK(physics.run(frame(0.0)).steps == 0);

    // Run to the end: the frames compute the rest, then the transport pauses and the run is over.
    PhysicsRequests to_end;
    to_end.run_to_end = true;
    out = physics.run(to_end);
    CHECK(out.running_to_end);
    for (int i = 0; i < 1000 && out.running_to_end; ++i) out = physics.run(frame(0.0));
    CHECK(!out.running_to_end);
    CHECK(!out.playing);
    CHECK(out.finished);
    CHECK(out.run_over());
    CHECK(!out.trouble);
    CHECK(physics.lanes().all_finished());

    // A restart is a new run: back to t = 0, not over.
    out = physics.run(restart_and_wait(true));
    CHECK(out.time_s == 0.0);
    CHECK(!out.run_over());
    CHECK(out.playing);

    // A lane the window found not finite stops everything before the frame steps.
    PhysicsRequests nan = frame(0.0);
    nan.non_finite_lane = 0;
    out = physics.run(nan);
    CHECK(out.trouble);
    CHECK(out.run_over());
    CHECK(out.steps == 0);
    REQUIRE(physics.lanes().trouble());
    CHECK_THAT(*physics.lanes().trouble(), Catch::Contains("non-finite"));
    // Neither stepping nor running to the end moves a troubled run.
    to_end = frame(0.0);
    to_end.step = true;
    to_end.run_to_end = true;
    out = physics.run(to_end);
    CHECK(out.steps == 0);
    CHECK(!out.running_to_end);
}

TEST_CASE("the window's physics keeps real time within its budget, builds in the background", "[app][physics]") {
    double now_s = 0.0;
    SandboxPhysics physics(false, [&] { return now_s; });
    PhysicsRequests start;
    start.restart_with = std::vector<Scene>{quick_scene()};
    start.play = true;
    PhysicsOutcome out = physics.run(start);
    CHECK(!out.built);  // building on its own thread; a frame's job takes it in once ready
    for (int i = 0; i < 2000 && !physics.lanes().ready(); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        out = physics.run(frame(0.0));
    }
    REQUIRE(physics.lanes().ready());
    // A frame of wall time with the clock frozen: the lanes reach the clock's target.
    out = physics.run(frame(0.05));
    CHECK(out.time_s == Approx(0.05).margin(1e-3));
    // Slow motion 1/4: a quarter of the frame's wall time.
    PhysicsRequests slow = frame(0.04);
    slow.frame->slow_divisor = 4;
    out = physics.run(slow);
    CHECK(out.time_s == Approx(0.06).margin(1e-3));
    CHECK(physics.clock().slow_divisor() == 4);
    // Pausing restarts the clock at the lanes' time: a long pause owes nothing.
    PhysicsRequests pause = frame(0.05);
    pause.play = false;
    CHECK(physics.run(pause).steps == 0);
    PhysicsRequests resume = frame(0.0);
    resume.play = true;
    out = physics.run(resume);
    CHECK(out.time_s == Approx(0.06).margin(1e-3));
}
