// `--model auto`'s rule: which models a scene needs, and why; see model_choice.h. The run that
// follows the rule (AutoRun) composes models, so it lives above them, in sim/registry/auto_run.h.
#include "sim/model_choice.h"

#include <stdexcept>
#include <string>

#include "sim/model_registry.h"
#include "sim/scene/scene_names.h"

namespace polyroll {

bool fill_is_solid(const Scene& scene) { return scene.fill.ratio >= 1.0; }

// The rule below in a line; its reasons are in each branch.
const char* auto_rule_description() {
    return "the cheapest model the scene needs: rigid for an empty or a full shell, going on as a free rigid body "
           "where it would lift off or slip; grains for a partly filled one";
}

namespace {

ModelChoice apply_rule(const Scene& scene) {
    ModelChoice c;
    // A curved track changes nothing here: the rigid model and the free body follow its local slope.
    if (scene.fill.ratio == 0.0) {
        c.model = Model::rigid;
        c.then = Model::grains;
        // A line or two as `polyroll run` prints it; docs/physics.md says the rest.
        c.reason =
            "empty shell: the rigid impact model is its exact limit (free to fly and slide), Box2D only at "
            "contacts it does not model (docs/physics.md)";
    } else if (fill_is_solid(scene)) {
        c.model = Model::rigid;
        c.then = Model::grains;
        c.reason =
            "full shell: its grains have no room to move, so shell and fill are one rigid polygon and the rigid "
            "impact model is its exact limit (free to fly and slide), Box2D only at contacts it does not model "
            "(docs/physics.md)";
    } else {
        // docs/tradeoff/tradeoff.md, over its 21 scenes against the reference.
        c.model = Model::grains;
        c.reason =
            "partly filled: the reduced models miss its terminal velocity by 27% (rigid) and 34% (segments), the "
            "grains by 5.6% (trade study: docs/tradeoff/tradeoff.md)";
    }
    return c;
}

// The registry's row says whether auto may use a model (ModelTraits::auto_may_pick): a rule that
// names another is a mistake in this file, not in the scene.
Model allowed(Model m) {
    if (!model_traits(m).auto_may_pick)
        throw std::logic_error("auto's rule picked the " + to_string(m) + " model, which the model registry keeps from it");
    return m;
}

}  // namespace

ModelChoice choose_model(const Scene& scene) {
    ModelChoice c = apply_rule(scene);
    c.model = allowed(c.model);
    if (c.then) c.then = allowed(*c.then);
    return c;
}

}  // namespace polyroll
