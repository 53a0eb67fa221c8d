// Builds the Box2D world of a scene: the ramp, the shell and its grains, settled in the release pose
// and ready to let go (or, for a run handed over from another model, moving as that model left it),
// from the parts in world_parts.h. The engine works in the ramp's frame: x down the slope, y along its
// normal, gravity tilted by the ramp angle, the ramp's surface at y = 0 from x = 0 (top) to x = length.
// Internal to sim/: outside it, runs are ModelRuns (model_run.h) and nothing names a Box2D type.
#pragma once

#include <memory>
#include <vector>

#include <box2d/box2d.h>

#include "sim/grains/engine_units.h"
#include "sim/grains/fill_plan.h"
#include "sim/grains/force_hook.h"
#include "sim/grains/near_pairs.h"
#include "sim/geometry/geometry.h"
#include "sim/scene/scene.h"
#include "sim/geometry/shell_pose.h"
#include "sim/geometry/shell_properties.h"

namespace polyroll {

// Sets the friction and restitution of each kind of contact when it begins (Box2D would mix the two
// fixtures' values; the scene gives them per pair).
class ContactMaterials : public b2ContactListener {
public:
    explicit ContactMaterials(const Scene& scene) : scene_(scene) {}
    void BeginContact(b2Contact* contact) override;

private:
    const Scene& scene_;
};

enum class BodyKind : uintptr_t { ramp = 1, shell = 2, grain = 3 };


struct SimWorld {
    Scene scene;
    EngineUnits units;
    ShellProperties shell_props;
    FillPlan fill;
    std::vector<geom::Vec2> outer_local_m;  // the shell's outer vertices in its own frame
    std::vector<geom::Vec2> inner_local_m;
    geom::Vec2 gravity_m_s2;                // in the ramp frame
    double start_centre_x_m = 0.0;          // the lid centre at release
    double end_centre_x_m = 0.0;            // the run ends when the centre passes this
    double settle_time_s = 0.0;             // how long the grains were given before release
    bool settled = true;                    // the grains came to rest within run.settle_time_s
    double balance_correction_deg = 0.0;    // turn that put the whole centre of mass past balance

    std::unique_ptr<ContactMaterials> materials;  // declared before the world: outlives it
    std::unique_ptr<NearPairs> near_pairs;        // likewise; null: Box2D's own contacts (near_pairs.h)
    std::unique_ptr<b2World> world;
    b2Body* ramp = nullptr;  // static; kinematic where the engine steps in the pile's frame (moving_frame.h)
    b2Body* shell = nullptr;
    std::vector<b2Body*> grains;
    std::vector<ForceHook> force_hooks;

    // One tracker step: fidelity.substeps engine steps, each after the force hooks, in the frame
    // fidelity.frame names (moving_frame.h).
    void step();
};

// Builds the world, settles the grains with the shell held, then frees the shell (at rest). The
// hooks act from the first settling step on.
std::unique_ptr<SimWorld> build_world(const Scene& scene, std::vector<ForceHook> hooks = {});

// The world of a run another model began: the shell in `shell`'s pose and moving with it, the grains
// (if any) poured unsettled in its frame and moving with it; positions are measured from the release
// centre `start_centre_x_m`.
std::unique_ptr<SimWorld> build_world_from(const Scene& scene, const ShellState& shell, double start_centre_x_m,
                                           std::vector<ForceHook> hooks = {});

}  // namespace polyroll
