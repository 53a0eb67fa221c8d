// Bare engine stepping for the benchmark: see bare_engine.h.
#include "sim/bare_engine.h"

#include <chrono>

#include "sim/world_builder.h"

namespace polyroll {

double time_bare_engine_s(const Scene& scene, long steps) {
    std::unique_ptr<SimWorld> bare = build_world(scene);
    const auto start = std::chrono::steady_clock::now();
    for (long i = 0; i < steps; ++i) bare->step();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace polyroll
