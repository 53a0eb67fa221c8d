// The model registry's table: one row per model, each naming its run's start (model_row.h). In
// sim/registry/, above the model wings (sim/grains/, sim/reduced/, sim/dem3d/), because it includes
// them all. A new model is a row here, its folder, and its value in scene.h's Model enum.
#include "sim/model_row.h"

#ifndef __EMSCRIPTEN__
#include "sim/dem3d/dem3d_run.h"
#endif
#include "sim/errors.h"
#include "sim/grains/simulation.h"
#include "sim/model_registry.h"
#include "sim/reduced/reduced_run.h"

namespace polyroll {

namespace {

std::unique_ptr<ModelRun> start_grains(const Scene& s) { return std::make_unique<Simulation>(s); }
std::unique_ptr<ModelRun> carry_on_grains(const Scene& s, const HandOver& from) {
    return std::make_unique<Simulation>(s, from);
}
std::unique_ptr<ModelRun> start_segments(const Scene& s) {
    return std::make_unique<models::ReducedRun>(s, models::FillMotion::relevel);
}
std::unique_ptr<ModelRun> start_rigid(const Scene& s) {
    return std::make_unique<models::ReducedRun>(s, models::FillMotion::frozen);
}
// The rigid model computes its whole run at once, so where it stops holding (lift-off or slip) is
// known from the start; computed only up to there: past it the model means nothing (and a shell that
// would hop can rock ever faster in it, costing a second of integration for nothing).
std::unique_ptr<ModelRun> start_rigid_while_valid(const Scene& s) {
    return std::make_unique<models::ReducedRun>(s, models::FillMotion::frozen, true);
}
std::unique_ptr<ModelRun> start_dem3d([[maybe_unused]] const Scene& s) {
#ifdef __EMSCRIPTEN__
    throw InputError("--model dem3d runs Yade as a separate program, which a web page cannot: use polyroll run "
                     "--model dem3d");
#else
    return std::make_unique<dem3d::Dem3dRun>(s);
#endif
}

}  // namespace

// Every trait named in every row (the compiler checks none is left out), in ModelTraits' order.
const std::vector<ModelRow>& model_rows() {
    static const std::vector<ModelRow> table = {
        {{.model = Model::grains,
          .name = "grains",
          .description = "Box2D simulates the shell and every grain",
          .engine = true,
          .has_grains = true,
          .fill_description = "",
          .continues_hand_over = true,
          .everyday = true,
          .follows_curved_track = true,
          .cost = RunCost::engine_bodies,
          .auto_may_pick = true,
          .reports_progress = false},
         start_grains, carry_on_grains, nullptr},
        {{.model = Model::segments,
          .name = "segments",
          .description = "the experimenters' reduced model with the fill as rigid segments that re-level after "
                         "each impact",
          .engine = false,
          .has_grains = false,
          .fill_description = "segments re-levelled at each impact",
          .continues_hand_over = false,
          .everyday = true,
          .follows_curved_track = true,
          .cost = RunCost::computed_whole,
          .auto_may_pick = false,
          .reports_progress = false},
         start_segments, nullptr, nullptr},
        {{.model = Model::rigid,
          .name = "rigid",
          .description = "the experimenters' reduced model with the fill frozen as at release",
          .engine = false,
          .has_grains = false,
          .fill_description = "a frozen rigid body",
          .continues_hand_over = false,
          .everyday = true,
          .follows_curved_track = true,
          .cost = RunCost::computed_whole,
          .auto_may_pick = true,
          .reports_progress = false},
         start_rigid, nullptr, start_rigid_while_valid},
        {{.model = Model::dem3d,
          .name = "dem3d",
          .description = "the 3D reference: Yade simulates the shell and every grain in 3D, about a minute a run",
          .engine = false,
          .has_grains = true,
          .fill_description = "",
          .continues_hand_over = false,
          .everyday = false,
          .follows_curved_track = true,
          .cost = RunCost::yade_grains,
          .auto_may_pick = false,
          .reports_progress = true},
         start_dem3d, nullptr, nullptr},
    };
    return table;
}

}  // namespace polyroll
