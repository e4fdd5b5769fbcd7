#include "python/src/json_conversion.h"

#include <cmath>

namespace py = pybind11;

namespace scatterlab::python {

nlohmann::json jsonFromPython(py::handle value, const std::string& where) {
  // bool before int: Python's True is an int too.
  if (value.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::int_>(value)) {
    try {
      return value.cast<int64_t>();
    } catch (const py::cast_error&) {
      throw py::value_error(where + ": the integer " + py::str(value).cast<std::string>() +
                            " does not fit in 64 bits");
    }
  }
  if (py::isinstance<py::float_>(value)) {
    const double number = value.cast<double>();
    if (!std::isfinite(number))
      throw py::value_error(where + ": " + py::repr(value).cast<std::string>() +
                            " is not a finite number (JSON has none)");
    return number;
  }
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::dict>(value)) {
    nlohmann::json object = nlohmann::json::object();
    for (const auto& [key, item] : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(key))
        throw py::value_error(where + ": the key " + py::repr(key).cast<std::string>() + " is not a string");
      const std::string name = key.cast<std::string>();
      object[name] = jsonFromPython(item, where.empty() ? name : where + "." + name);
    }
    return object;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    nlohmann::json array = nlohmann::json::array();
    size_t index = 0;
    for (const py::handle item : value)
      array.push_back(jsonFromPython(item, where + "[" + std::to_string(index++) + "]"));
    return array;
  }
  // numpy scalars (np.float64(0.2), np.int64(3)) are numbers too.
  if (py::hasattr(value, "dtype") && py::hasattr(value, "item") && py::len(value.attr("shape")) == 0)
    return jsonFromPython(value.attr("item")(), where);
  throw py::value_error((where.empty() ? std::string("material") : where) + ": a value of type " +
                        py::str(value.get_type().attr("__name__")).cast<std::string>() +
                        " cannot be part of a material description (dict, list, str, number, bool or None)");
}

py::object pythonFromJson(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::null: return py::none();
    case nlohmann::json::value_t::boolean: return py::bool_(value.get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(value.get<int64_t>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(value.get<uint64_t>());
    case nlohmann::json::value_t::number_float: return py::float_(value.get<double>());
    case nlohmann::json::value_t::string: return py::str(value.get<std::string>());
    case nlohmann::json::value_t::array: {
      py::list list;
      for (const nlohmann::json& item : value) list.append(pythonFromJson(item));
      return list;
    }
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (const auto& [key, item] : value.items()) dict[py::str(key)] = pythonFromJson(item);
      return dict;
    }
    default: return py::none();  // binary and discarded values never occur in scatterlab's JSON
  }
}

}  // namespace scatterlab::python
