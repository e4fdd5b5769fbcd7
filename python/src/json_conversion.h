// Python values <-> JSON, for material descriptions given as dicts and results returned as
// dicts and lists (docs/python.md).
#pragma once

#include <string>

#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

namespace scatterlab::python {

// A dict, list, tuple, str, bool, int, float or None, nested, as JSON. Raises ValueError naming
// the key path (`where`, then "materials[1].alpha") of a value of any other type, of a dict key
// that is not a string, and of a float that is not finite (JSON has no NaN; the registry's
// messages name the key of a value out of range, but a NaN must not get that far).
nlohmann::json jsonFromPython(pybind11::handle value, const std::string& where);

// JSON as Python: objects as dicts, arrays as lists.
pybind11::object pythonFromJson(const nlohmann::json& value);

}  // namespace scatterlab::python
