// The scene's enumeration names: see scene_names.h.
#include "sim/scene/scene_names.h"

#include <array>
#include <utility>

#include "sim/model_row.h"

namespace polyroll {
namespace {

// Each enum value beside its name; the lists below and the lookups are built from these alone.
constexpr std::array<std::pair<ReleasePose, std::string_view>, 3> kPoses = {{
    {ReleasePose::vertex, "vertex"},
    {ReleasePose::face, "face"},
    {ReleasePose::tipped, "tipped"},
}};
// A model's name is its registry row's (model_row.h); auto is a rule over the rows, not a row, and
// is named here.
constexpr std::string_view kAutoName = "auto";

constexpr std::array<std::pair<EngineFrame, std::string_view>, 2> kFrames = {{
    {EngineFrame::ramp, "ramp"},
    {EngineFrame::pile, "pile"},
}};

constexpr std::array<std::pair<GrainContacts, std::string_view>, 2> kContacts = {{
    {GrainContacts::boxes, "boxes"},
    {GrainContacts::near, "near"},
}};

template <class E, std::size_t N>
std::string name_of(const std::array<std::pair<E, std::string_view>, N>& table, E value) {
    for (const auto& [v, name] : table)
        if (v == value) return std::string(name);
    return "unknown";
}

template <class E, std::size_t N>
std::vector<std::string> names_of(const std::array<std::pair<E, std::string_view>, N>& table) {
    std::vector<std::string> names;
    names.reserve(N);
    for (const auto& entry : table) names.emplace_back(entry.second);
    return names;
}

template <class E, std::size_t N>
std::optional<E> value_named(const std::array<std::pair<E, std::string_view>, N>& table, std::string_view name) {
    for (const auto& [v, n] : table)
        if (n == name) return v;
    return std::nullopt;
}

}  // namespace

std::string to_string(ReleasePose pose) { return name_of(kPoses, pose); }
std::string to_string(Model model) {
    if (model == Model::automatic) return std::string(kAutoName);
    for (const ModelRow& r : model_rows())
        if (r.traits.model == model) return r.traits.name;
    return "unknown";
}
std::string to_string(EngineFrame frame) { return name_of(kFrames, frame); }
std::string to_string(GrainContacts contacts) { return name_of(kContacts, contacts); }

const std::vector<std::string>& release_pose_names() {
    static const std::vector<std::string> names = names_of(kPoses);
    return names;
}
const std::vector<std::string>& model_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const ModelRow& r : model_rows()) n.push_back(r.traits.name);
        n.emplace_back(kAutoName);
        return n;
    }();
    return names;
}

std::optional<ReleasePose> release_pose_named(std::string_view name) { return value_named(kPoses, name); }
std::optional<Model> model_named(std::string_view name) {
    if (name == kAutoName) return Model::automatic;
    for (const ModelRow& r : model_rows())
        if (r.traits.name.get() == name) return r.traits.model.get();
    return std::nullopt;
}
const std::vector<std::string>& engine_frame_names() {
    static const std::vector<std::string> names = names_of(kFrames);
    return names;
}
std::optional<EngineFrame> engine_frame_named(std::string_view name) { return value_named(kFrames, name); }
const std::vector<std::string>& grain_contacts_names() {
    static const std::vector<std::string> names = names_of(kContacts);
    return names;
}
std::optional<GrainContacts> grain_contacts_named(std::string_view name) { return value_named(kContacts, name); }

}  // namespace polyroll
