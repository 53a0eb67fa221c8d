// The scene's fields, one row each: where it lives in a scene file and in Scene, its type and limits,
// its unit, its command-line flag, its label on the sandbox panel and its help text. Reading and
// writing scene JSON (scene_json.cpp), the range checks (scene_validate.cpp), the scene flags of the
// commands (cli/scene_options.cpp, cli/sweep_command.cpp) and the panel's ranges and tooltips
// (app/) all read this table: adding a field to Scene is adding one row here.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "sim/assets.h"
#include "sim/scene/scene.h"

namespace polyroll {

// One field's value, whatever its type.
using FieldValue = std::variant<int, double, std::optional<double>, std::uint64_t, std::string, ReleasePose, Model, EngineFrame, GrainContacts>;

enum class FieldType {
    integer,          // int: a whole number
    number,           // double: a finite number
    optional_number,  // std::optional<double>: a finite number, or null for none
    seed,             // std::uint64_t: a whole number from 0 to 2^64-1
    preset,           // std::string: the name of a preset of the section's kind (assets/)
    choice,           // an enumeration: one of its names (scene_names.h)
};

// Reads and writes the field's member of a Scene.
struct FieldAccess {
    FieldValue (*get)(const Scene&) = nullptr;
    void (*set)(Scene&, const FieldValue&) = nullptr;
};

// The accessor of the member reached by a chain of member pointers, e.g.
// member<&Scene::fill, &FillParams::material, &MaterialParams::friction>().
template <auto... Members>
constexpr FieldAccess member() {
    return {[](const Scene& s) { return FieldValue((s .* ... .* Members)); },
            [](Scene& s, const FieldValue& v) {
                auto& m = (s .* ... .* Members);
                m = std::get<std::decay_t<decltype(m)>>(v);
            }};
}

struct SceneField {
    std::string_view path;  // as in a scene file: "fill.material.wall_friction"
    FieldType type = FieldType::number;
    FieldAccess access;
    // Limits of a number: min <= value <= max, strictly where open. A limit that depends on other
    // fields is a function of the scene instead (min_of, max_of); the fields it reads are listed in
    // depends_on, and validation checks those first.
    double min = 0.0, max = 0.0;
    bool min_open = false, max_open = false;
    double (*min_of)(const Scene&) = nullptr;
    double (*max_of)(const Scene&) = nullptr;
    std::vector<std::string_view> depends_on;
    std::string_view unit;        // shown after the limits in messages: "m", "degrees"; "" for none
    std::string_view limit_note;  // shown after the unit, e.g. "(at most fidelity.step_hz)"
    std::optional<assets::Kind> kind;  // preset fields: which presets (assets/)
    const std::vector<std::string>& (*choice_names)() = nullptr;           // choice fields: the names,
    std::optional<FieldValue> (*choice_named)(std::string_view) = nullptr;  // and the value of a name
    std::string_view flag;        // command-line flag, e.g. "--angle"; "" for none
    int sweep_axis = 0;           // place among polyroll sweep's axis flags (1 = outermost); 0 = none
    std::string_view label;       // the sandbox panel's label for its control ("" = no control)
    std::string_view help;        // what the field is: --help text and the panel's tooltip
};

// Every field, in scene-file order (the order scene_to_json writes them).
const std::vector<SceneField>& scene_fields();

// The field at `path`; throws std::logic_error for a path that is not in the table (a code defect).
const SceneField& scene_field(std::string_view path);

// "fill.material.friction" -> "fill.material" and "friction".
std::string_view section_of(std::string_view path);
std::string_view key_of(std::string_view path);

// The limits of a number field for this scene (the dynamic ones computed).
double field_min(const SceneField& f, const Scene& s);
double field_max(const SceneField& f, const Scene& s);

// What a preset or choice field accepts: the preset names (assets/) or the enumeration's names.
std::vector<std::string> field_choices(const SceneField& f);

// What the field accepts, for help texts: "3 to 64", "from 0 to 89 degrees", "bb, rice, peas".
std::string field_allowed(const SceneField& f);

// The help text with what is allowed: "n: the number of sides of the hollow polygon: 3 to 64".
std::string field_help(const SceneField& f);

}  // namespace polyroll
