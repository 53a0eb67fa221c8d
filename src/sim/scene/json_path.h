// "a.b.c" paths into JSON documents (the scene fields' names): the one walk from a dotted path to
// its node, doc["a"]["b"]["c"], for every layer that turns field paths into documents or reads them.
#pragma once

#include <string_view>

#include <nlohmann/json.hpp>

namespace polyroll {

// What to do with a section met on the way that holds a preset name ("material": "bb").
enum class PresetSections {
    keep,  // as it is: indexing it fails as indexing a string does
    open,  // made {"preset": "bb"}, so it can take fields
};

// The node at `path`, made (null) where missing, with the objects on the way.
nlohmann::ordered_json& node_at(nlohmann::ordered_json& doc, std::string_view path,
                                PresetSections sections = PresetSections::keep);

// The node at `path`, or nullptr where a part is missing or its parent is not an object.
const nlohmann::ordered_json* find_at(const nlohmann::ordered_json& doc, std::string_view path);

}  // namespace polyroll
