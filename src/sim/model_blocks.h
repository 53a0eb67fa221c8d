// RunResult::model_blocks: what only the model that ran has to say, each a block of summary.json
// under its key (Box2D's "engine", the 3D reference's "dem3d_engine"). The JSON object sits behind a
// pointer so that naming a RunResult does not compile nlohmann/json.hpp: some thirty files include
// run_result.h and need nothing else of JSON, and that header costs each of them about 9 CPU-seconds
// of clang-tidy (CI's longest step, docs/testing.md) and seconds of compiling. A file that reads or
// writes a block includes <nlohmann/json.hpp> itself.
#pragma once

#include <memory>

#include <nlohmann/json_fwd.hpp>

namespace polyroll {

class ModelBlocks {
public:
    ModelBlocks();  // an empty object
    ~ModelBlocks();
    ModelBlocks(const ModelBlocks& other);
    ModelBlocks& operator=(const ModelBlocks& other);
    ModelBlocks(ModelBlocks&& other) noexcept;
    ModelBlocks& operator=(ModelBlocks&& other) noexcept;

    // The blocks as one JSON object, key -> block. A moved-from ModelBlocks reads as empty and
    // starts a new object when written.
    nlohmann::ordered_json& json();
    const nlohmann::ordered_json& json() const;

private:
    std::unique_ptr<nlohmann::ordered_json> json_;
};

}  // namespace polyroll
