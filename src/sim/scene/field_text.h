// A scene field's value from the words a person typed: a command-line flag's value (polyroll's and
// the window's) or a web page address's. Every surface reads typed text here, so "six" for n is refused
// in the same words everywhere ("not a whole number (allowed: 3 to 64)"); the value's range, preset
// or choice is then checked where every value is, when the scene is resolved (scene_json.h), in the
// words the command line uses ("shell.sides = 2 (from --sides) is out of range (allowed: 3 to 64)").
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "sim/scene/scene_fields.h"

namespace polyroll {

// What is wrong with `text` as a value of the field's type, or "" when nothing is: "not a whole number
// (allowed: 3 to 64)", "not a number (allowed: from 0 to 1)", "out of range (allowed: 0 to 2^64-1)"
// for digits past the type. A preset's or a choice's name is any text here.
std::string field_text_problem(const SceneField& f, std::string_view text);

// The text as the field's JSON value (a number, a whole number, a name; "null" for an optional number's
// none). Throws InputError "<said>: <problem>" where field_text_problem finds one; `said` is the
// setting as typed, "--sides six" or "sides=six".
nlohmann::ordered_json field_json_from_text(const SceneField& f, const std::string& text, const std::string& said);

// The name a surface without dashes gives the field: its flag without them ("--sides" -> "sides"), the
// web page's address key and the window's flag's name.
std::string field_key(const SceneField& f);

}  // namespace polyroll
