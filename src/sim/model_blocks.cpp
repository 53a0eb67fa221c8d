#include "sim/model_blocks.h"

#include <nlohmann/json.hpp>

namespace polyroll {

ModelBlocks::ModelBlocks() : json_(std::make_unique<nlohmann::ordered_json>(nlohmann::ordered_json::object())) {}
ModelBlocks::~ModelBlocks() = default;
ModelBlocks::ModelBlocks(const ModelBlocks& other) : json_(std::make_unique<nlohmann::ordered_json>(other.json())) {}
ModelBlocks& ModelBlocks::operator=(const ModelBlocks& other) {
    if (this != &other) json_ = std::make_unique<nlohmann::ordered_json>(other.json());
    return *this;
}
ModelBlocks::ModelBlocks(ModelBlocks&& other) noexcept = default;
ModelBlocks& ModelBlocks::operator=(ModelBlocks&& other) noexcept = default;

nlohmann::ordered_json& ModelBlocks::json() {
    if (!json_) json_ = std::make_unique<nlohmann::ordered_json>(nlohmann::ordered_json::object());
    return *json_;
}

const nlohmann::ordered_json& ModelBlocks::json() const {
    static const nlohmann::ordered_json empty = nlohmann::ordered_json::object();
    return json_ ? *json_ : empty;
}

}  // namespace polyroll
