// "a.b.c" paths into JSON documents: see json_path.h.
#include "sim/scene/json_path.h"

#include <algorithm>
#include <string>

namespace polyroll {

nlohmann::ordered_json& node_at(nlohmann::ordered_json& doc, std::string_view path, PresetSections sections) {
    nlohmann::ordered_json* node = &doc;
    std::size_t start = 0;
    for (std::size_t dot = path.find('.'); dot != std::string_view::npos; dot = path.find('.', start)) {
        nlohmann::ordered_json& child = (*node)[std::string(path.substr(start, dot - start))];
        if (sections == PresetSections::open && child.is_string()) child = nlohmann::ordered_json{{"preset", child}};
        node = &child;
        start = dot + 1;
    }
    return (*node)[std::string(path.substr(start))];
}

const nlohmann::ordered_json* find_at(const nlohmann::ordered_json& doc, std::string_view path) {
    const nlohmann::ordered_json* node = &doc;
    for (std::size_t start = 0; start <= path.size();) {
        const std::size_t dot = std::min(path.find('.', start), path.size());
        const std::string key(path.substr(start, dot - start));
        if (!node->is_object() || !node->contains(key)) return nullptr;
        node = &node->at(key);
        start = dot + 1;
    }
    return node;
}

}  // namespace polyroll
