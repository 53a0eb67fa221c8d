// Bare engine stepping for the benchmark: see bare_engine.h.
#include "sim/grains/bare_engine.h"

#include <algorithm>

#include "sim/grains/world_builder.h"
#include "sim/wall_clock.h"

namespace polyroll {

double time_bare_engine_s(const Scene& scene, long steps) {
    std::unique_ptr<SimWorld> bare = build_world(scene);
    const auto start = WallClock::now();
    for (long i = 0; i < steps; ++i) bare->step();
    return seconds_since(start);
}

EngineLoad measure_engine_load(const Scene& scene, long steps, long skip_steps) {
    std::unique_ptr<SimWorld> w = build_world(scene);
    for (long i = 0; i < skip_steps; ++i) w->step();
    EngineLoad load;
    load.grains = static_cast<int>(w->grains.size());
    load.shell_speed_m_s = w->units.to_m(w->shell->GetLinearVelocity().x);
    const auto on_ramp = [&] { return w->units.to_m(w->shell->GetPosition().x) < w->end_centre_x_m; };
    // Counting walks every contact: sampled every 100th step, outside the timed stretches.
    constexpr long kSampleEvery = 100;
    long samples = 0, contacts = 0, touching = 0;
    for (long done = 0; done < steps && on_ramp();) {
        const long stretch = std::min(kSampleEvery, steps - done);
        const auto start = WallClock::now();
        for (long i = 0; i < stretch; ++i) w->step();
        load.wall_s += seconds_since(start);
        done += stretch;
        load.timed_steps = done;
        for (const b2Contact* c = w->world->GetContactList(); c != nullptr; c = c->GetNext()) {
            ++contacts;
            if (c->IsTouching()) ++touching;
        }
        ++samples;
    }
    if (samples > 0 && load.grains > 0) {
        load.contacts_per_grain = static_cast<double>(contacts) / static_cast<double>(samples * load.grains);
        load.touching_per_grain = static_cast<double>(touching) / static_cast<double>(samples * load.grains);
    }
    return load;
}

}  // namespace polyroll
