// What a run's caller hands it on its thread (sim/run_progress.h, sim/run_cores.h): a stop hook that
// ends a run between steps, and the cores a run may use, shared among a sweep's jobs, which set the
// 3D reference's threads inside a Slurm allocation.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <optional>
#include <string>

#include "sim/dem3d/yade_process.h"
#include "sim/errors.h"
#include "sim/model_registry.h"
#include "sim/run_cores.h"
#include "sim/run_progress.h"
#include "test_helpers.h"

using namespace polyroll;
using polyroll::test::scene_with;

TEST_CASE("a stop hook ends a run between steps with RunStopped, and without one it runs to its end") {
    const Scene scene = scene_with({{"fill", {{"ratio", 0.25}}}, {"run", {{"time_limit_s", 1.0}}}});
    std::unique_ptr<ModelRun> run = start_run(scene);
    int asked = 0;
    {
        const ScopedRunStop stop([&asked] { return ++asked > 50; });
        CHECK(run_stop_hooked());
        CHECK_THROWS_AS(run->run_to_end(), RunStopped);
    }
    CHECK(asked == 51);
    CHECK(run->steps() == 51);  // the hook is asked after each step
    CHECK_FALSE(run->finished());
    CHECK_FALSE(run_stop_hooked());
    CHECK_FALSE(run_stop_requested());
    // The same run carries on to its end once no one asks it to stop.
    run->run_to_end();
    CHECK(run->finished());
}

TEST_CASE("the cores a run may use: the process's, a sweep job's share, SLURM_CPUS_PER_TASK's bound") {
    const int all = process_cores();
    CHECK(all >= 1);
    CHECK(run_cores() == all);
    {
        const ScopedRunCores one(1);
        CHECK(run_cores() == 1);
        {
            const ScopedRunCores none(0);  // never less than one
            CHECK(run_cores() == 1);
        }
    }
    CHECK(run_cores() == all);
}

namespace {

// Sets (or unsets, for null) an environment variable until the scope ends.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) before_ = old;
        if (value)
            ::setenv(name, value, 1);
        else
            ::unsetenv(name);
    }
    ~ScopedEnv() {
        if (before_)
            ::setenv(name_, before_->c_str(), 1);
        else
            ::unsetenv(name_);
    }

private:
    const char* name_;
    std::optional<std::string> before_;
};

}  // namespace

TEST_CASE("a Slurm allocation bounds the cores, and the 3D reference has one thread outside it") {
    const int all = process_cores();
    {
        const ScopedEnv slurm("SLURM_CPUS_PER_TASK", nullptr);
        const ScopedEnv threads("POLYROLL_DEM3D_THREADS", nullptr);
        CHECK_FALSE(in_allocation());
        CHECK(dem3d::threads() == 1);  // on a shared machine: reproducible, and no threads waiting on each other
        const ScopedRunCores two(2);
        CHECK(dem3d::threads() == 1);
    }
    {
        const ScopedEnv slurm("SLURM_CPUS_PER_TASK", "1");
        CHECK(in_allocation());
        CHECK(process_cores() == 1);
        CHECK(dem3d::threads() == 1);
    }
    {
        const ScopedEnv slurm("SLURM_CPUS_PER_TASK", "64");
        CHECK(process_cores() == all);  // the affinity bounds it too
        CHECK(dem3d::threads() == all);
        const ScopedRunCores share(1);  // a sweep job's share of the task's cores
        CHECK(dem3d::threads() == 1);
    }
    {
        const ScopedEnv slurm("SLURM_CPUS_PER_TASK", "not-a-number");
        CHECK(process_cores() == all);
    }
    {
        const ScopedEnv threads("POLYROLL_DEM3D_THREADS", "3");
        CHECK(dem3d::threads() == 3);
    }
    for (const char* bad : {"0", "65", "two", "2x", "-1"}) {
        const ScopedEnv threads("POLYROLL_DEM3D_THREADS", bad);
        CHECK_THROWS_WITH(dem3d::threads(), Catch::Contains(std::string("POLYROLL_DEM3D_THREADS=") + bad) &&
                                                 Catch::Contains("from 1 to 64"));
    }
}
