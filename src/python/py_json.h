// Python values to and from scene JSON: the module hands scene documents, summaries and values of
// scene fields across as the same JSON the command line reads and writes.
#pragma once

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

namespace polyroll::python {

// None, bool, int, float, str, dict (str keys), list or tuple, and anything with __float__ or
// __index__ (numpy's scalars); throws InputError naming `what` for anything else.
nlohmann::ordered_json to_json(pybind11::handle value, const std::string& what);

// Objects to dicts (in order), arrays to lists, numbers to int or float.
pybind11::object from_json(const nlohmann::ordered_json& value);

}  // namespace polyroll::python
