// A registry row as sim/registry/model_rows.cpp writes one. Compiled twice by ctest: as it is (it
// must compile), and with OMIT_TRAIT defined, a row that leaves a trait out (it must not: every trait
// is Required, model_row.h).
#include "sim/model_row.h"

polyroll::ModelTraits row() {
    return {.model = polyroll::Model::grains,
            .name = "grains",
            .description = "a model",
            .engine = true,
            .has_grains = true,
            .fill_description = "",
            .continues_hand_over = false,
            .everyday = true,
            .follows_curved_track = true,
            .cost = polyroll::RunCost::engine_bodies,
            .auto_may_pick = false,
#ifndef OMIT_TRAIT
            .reports_progress = false
#endif
    };
}
