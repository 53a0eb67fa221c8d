// The names of the scene's enumerations, as scene files, flags, tables and the panel write them: one
// list per enum, in the enum's order, so no other file keeps an array that must match an enum.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sim/scene/scene.h"

namespace polyroll {

std::string to_string(ReleasePose pose);
std::string to_string(Model model);
std::string to_string(EngineFrame frame);
std::string to_string(GrainContacts contacts);

// Every value's name: the poses in the enum's order ("vertex", "face", "tipped"); the models' names
// from their registry rows in the rows' order, then "auto" (model_row.h).
const std::vector<std::string>& release_pose_names();
const std::vector<std::string>& model_names();

// The value named `name`, or nothing for a name not in the list.
std::optional<ReleasePose> release_pose_named(std::string_view name);
std::optional<Model> model_named(std::string_view name);
// "ramp", "pile"
const std::vector<std::string>& engine_frame_names();
std::optional<EngineFrame> engine_frame_named(std::string_view name);
// "boxes", "near"
const std::vector<std::string>& grain_contacts_names();
std::optional<GrainContacts> grain_contacts_named(std::string_view name);

}  // namespace polyroll
