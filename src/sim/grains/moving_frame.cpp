// The engine stepped in a frame moving with the pile: see moving_frame.h.
#include "sim/grains/moving_frame.h"

#include <cmath>

#include "sim/grains/world_builder.h"

namespace polyroll {

namespace {
void add_velocity(b2Body* b, float du) {
    // SetLinearVelocity wakes a sleeping body when the new velocity is not zero: a grain that slept
    // (at rest on the ramp, out of the shell) moves with the frame's ramp while the frame moves.
    b->SetLinearVelocity(b->GetLinearVelocity() + b2Vec2(du, 0.0f));
}
}  // namespace

float frame_velocity_units(const SimWorld& w) {
    if (w.scene.fidelity.frame != EngineFrame::pile || w.grains.empty()) return 0.0f;
    // Held while the grains settle, the shell is static and cannot take the frame's velocity; asleep,
    // nothing moves and there is nothing to gain.
    if (w.shell->GetType() != b2_dynamicBody || !w.shell->IsAwake()) return 0.0f;
    double sum_units_s = 0.0;
    for (const b2Body* b : w.grains) sum_units_s += b->GetLinearVelocity().x;
    const double u = sum_units_s / static_cast<double>(w.grains.size());
    // Below Box2D's sleep tolerance the ramp's velocity would keep the pile awake for nothing.
    return std::abs(u) > b2_linearSleepTolerance ? static_cast<float>(u) : 0.0f;
}

void step_in_frame(SimWorld& w, float dt, float u) {
    const FidelityParams& f = w.scene.fidelity;
    if (w.near_pairs) w.near_pairs->before_step(w);
    if (u == 0.0f) {
        w.world->Step(dt, f.velocity_iterations, f.position_iterations);
        return;
    }
    w.shell->SetLinearVelocity(w.shell->GetLinearVelocity() - b2Vec2(u, 0.0f));
    for (b2Body* b : w.grains) add_velocity(b, -u);
    w.ramp->SetLinearVelocity({-u, 0.0f});
    w.world->Step(dt, f.velocity_iterations, f.position_iterations);
    w.ramp->SetLinearVelocity({0.0f, 0.0f});  // between steps the ramp is still, as in its own frame
    w.shell->SetLinearVelocity(w.shell->GetLinearVelocity() + b2Vec2(u, 0.0f));
    for (b2Body* b : w.grains) add_velocity(b, u);
    // The ramp (at the origin, add_ramp) moved by -u dt, computed as Box2D's island does (h v, one
    // rounding); shifting by the same float product puts it back at exactly 0, and moves everything
    // else by +u dt.
    const float travel = dt * -u;
    w.world->ShiftOrigin({travel, 0.0f});
}

}  // namespace polyroll
