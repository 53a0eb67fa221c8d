// Python values to and from JSON: see py_json.h.
#include "python/py_json.h"

#include <string>
#include <string_view>

#include <fmt/core.h>

#include "sim/errors.h"

namespace py = pybind11;

namespace polyroll::python {

using json = nlohmann::ordered_json;

std::string a_type_name(py::handle value) {
    const std::string name = py::type::of(value).attr("__name__").cast<std::string>();
    const bool vowel = !name.empty() && std::string_view("aeiouAEIOU").find(name.front()) != std::string_view::npos;
    return (vowel ? "an " : "a ") + name;
}

json to_json(py::handle value, const std::string& what) {
    if (value.is_none()) return nullptr;
    if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
    if (py::isinstance<py::int_>(value)) {
        // A whole number JSON keeps exact: a seed may be up to 2^64-1, a negative number is an int64.
        if (value.cast<py::int_>() < py::int_(0)) return value.cast<long long>();
        try {
            return value.cast<unsigned long long>();
        } catch (const py::cast_error&) {
            throw InputError(fmt::format("{}: {} is too large (allowed: up to 2^64-1)", what, py::str(value).cast<std::string>()));
        }
    }
    if (py::isinstance<py::float_>(value)) return value.cast<double>();
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    if (py::isinstance<py::dict>(value)) {
        json out = json::object();
        for (const auto& [key, item] : value.cast<py::dict>()) {
            if (!py::isinstance<py::str>(key))
                throw py::type_error(fmt::format("{}: the key {} is not a string", what, py::repr(key).cast<std::string>()));
            const std::string k = key.cast<std::string>();
            out[k] = to_json(item, what + "." + k);
        }
        return out;
    }
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
        json out = json::array();
        for (const py::handle item : value) out.push_back(to_json(item, what));
        return out;
    }
    // numpy's integer and float scalars (np.int64(8), np.float64(0.375)).
    if (py::hasattr(value, "__index__")) return to_json(py::int_(py::reinterpret_borrow<py::object>(value)), what);
    if (py::hasattr(value, "__float__")) return to_json(py::float_(py::reinterpret_borrow<py::object>(value)), what);
    // A value of the wrong type is Python's TypeError (json.dumps says the same of such an object).
    throw py::type_error(fmt::format("{}: {} is not a scene value (allowed: a number, a string, None, a list or a dict)",
                                     what, a_type_name(value)));
}

py::object from_json(const json& value) {
    switch (value.type()) {
        case json::value_t::null: return py::none();
        case json::value_t::boolean: return py::bool_(value.get<bool>());
        case json::value_t::number_integer: return py::int_(value.get<long long>());
        case json::value_t::number_unsigned: return py::int_(value.get<unsigned long long>());
        case json::value_t::number_float: return py::float_(value.get<double>());
        case json::value_t::string: return py::str(value.get<std::string>());
        case json::value_t::array: {
            py::list out;
            for (const json& item : value) out.append(from_json(item));
            return out;
        }
        case json::value_t::object: {
            py::dict out;
            for (const auto& [key, item] : value.items()) out[py::str(key)] = from_json(item);
            return out;
        }
        default: return py::none();  // binary and discarded values never appear in polyroll's documents
    }
}

}  // namespace polyroll::python
