// Python values to and from scene JSON: the module hands scene documents, summaries and values of
// scene fields across as the same JSON the command line reads and writes.
#pragma once

#include <string>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

namespace polyroll::python {

// None, bool, int, float, str, dict (str keys), list or tuple, and anything with __float__ or
// __index__ (numpy's scalars); throws pybind11::type_error (TypeError) naming `what` for anything else,
// InputError (ValueError) for a whole number past 2^64-1.
nlohmann::ordered_json to_json(pybind11::handle value, const std::string& what);

// "an int", "a str": the value's type with its article, for messages.
std::string a_type_name(pybind11::handle value);

// Objects to dicts (in order), arrays to lists, numbers to int or float.
pybind11::object from_json(const nlohmann::ordered_json& value);

}  // namespace polyroll::python
