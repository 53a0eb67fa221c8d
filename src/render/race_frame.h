// A race's frame (polyroll render --preset NAME of a preset with several lanes): the lanes side by
// side as the window shows them (scene_view.h: the stacked ramps, the lanes' colours and numbered
// badges, the close-up of lane 1), under a panel naming each lane with its measurements and a speed
// plot with one curve per lane. No GL: render_sequence draws it, tests read it.
#pragma once

#include <string>
#include <vector>

#include "render/draw_list.h"
#include "render/font.h"
#include "render/frame_layout.h"
#include "render/snapshot.h"
#include "sim/measurements.h"

namespace polyroll::render {

// `outcomes`: each lane's ending on the held frames (race_outcome_text), or empty while the race
// runs. The options' plot axes and colour map hold for every lane.
DrawList build_race_frame(const std::vector<Snapshot>& lanes, const FrameOptions& o,
                          const std::vector<std::string>& outcomes, const FontAtlas& font);

// A lane's ending in a few words, for the panel's row beside its distance: "stopped at its first
// impact", "rolled to the end", "time limit reached" ("" while running).
std::string race_outcome_text(Behaviour b);

// Every font size a race frame of these options uses.
std::vector<FontSpec> race_frame_fonts(const FrameOptions& o);

}  // namespace polyroll::render
