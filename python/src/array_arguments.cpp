#include "python/src/array_arguments.h"

#include <cmath>
#include <sstream>

namespace py = pybind11;

namespace scatterlab::python {
namespace {

// |w| = 1 within this: the models assume unit directions (materials/bsdf/bsdf.h), and a
// direction normalised in float64 is within a few ulp of it.
constexpr double UnitLengthTolerance = 1e-6;

std::string shapeText(const py::array& array) {
  std::ostringstream text;
  text << "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) text << (d ? ", " : "") << array.shape(d);
  text << (array.ndim() == 1 ? ",)" : ")");
  return text.str();
}

std::string expectedShape(size_t width) { return width == 1 ? "(N,)" : "(N, " + std::to_string(width) + ")"; }

// The float64 array behind `value`, refusing every other dtype (and lists of non-numbers).
py::array_t<double, py::array::c_style> float64Array(py::handle value, const char* name, size_t width) {
  py::array array;
  if (py::isinstance<py::array>(value)) {
    array = py::reinterpret_borrow<py::array>(value);
  } else {
    // A list or tuple of floats, or a float: numpy decides its dtype, which must then be float64.
    try {
      array = py::module_::import("numpy").attr("asarray")(value);
    } catch (const py::error_already_set&) {
      throw py::value_error(std::string(name) + ": expected a float64 array of shape " +
                            expectedShape(width));
    }
    if (array.dtype().kind() == 'i' || array.dtype().kind() == 'u')  // [0, 0, 1] from a literal
      array = array.attr("astype")("float64");
  }
  if (!array.dtype().is(py::dtype::of<double>()))
    throw py::value_error(std::string(name) + ": expected a float64 array of shape " + expectedShape(width) +
                          ", got dtype " + py::str(array.dtype()).cast<std::string>() +
                          " (convert with .astype(numpy.float64))");
  return py::array_t<double, py::array::c_style>::ensure(array);
}

ArrayRows rowsOf(py::handle value, const char* name, size_t width) {
  const auto array = float64Array(value, name, width);
  const py::ssize_t ndim = array.ndim();
  if (width == 1 && ndim == 0) return ArrayRows(array, 1, 1, true);
  if (width == 1 && ndim == 1) return ArrayRows(array, size_t(array.shape(0)), 1, false);
  if (width > 1 && ndim == 1 && size_t(array.shape(0)) == width) return ArrayRows(array, 1, width, true);
  if (width > 1 && ndim == 2 && size_t(array.shape(1)) == width)
    return ArrayRows(array, size_t(array.shape(0)), width, false);
  throw py::value_error(std::string(name) + ": expected shape " + expectedShape(width) +
                        (width > 1 ? " or (" + std::to_string(width) + ",)" : std::string()) + ", got " +
                        shapeText(array));
}

std::string rowText(const ArrayRows& rows, size_t row, size_t width) {
  std::ostringstream text;
  text.precision(17);
  text << (width > 1 ? "(" : "");
  for (size_t c = 0; c < width; ++c) text << (c ? ", " : "") << rows.value(row, c);
  text << (width > 1 ? ")" : "");
  return text.str();
}

std::string indexed(const char* name, const ArrayRows& rows, size_t row) {
  return rows.broadcasts() ? std::string(name) : std::string(name) + "[" + std::to_string(row) + "]";
}

}  // namespace

ArrayRows directionArgument(py::handle value, const char* name) {
  ArrayRows rows = rowsOf(value, name, 3);
  for (size_t i = 0; i < rows.rows(); ++i) {
    const Vec3d w = rows.direction(i);
    if (!isFinite(w))
      throw py::value_error(indexed(name, rows, i) + " = " + rowText(rows, i, 3) + " is not finite");
    if (std::abs(length(w) - 1.0) > UnitLengthTolerance)
      throw py::value_error(indexed(name, rows, i) + " = " + rowText(rows, i, 3) + " has length " +
                            std::to_string(length(w)) +
                            "; directions must be unit vectors (|w| = 1 within 1e-6)");
  }
  return rows;
}

ArrayRows unitIntervalArgument(py::handle value, const char* name, size_t width) {
  ArrayRows rows = rowsOf(value, name, width);
  for (size_t i = 0; i < rows.rows(); ++i)
    for (size_t c = 0; c < width; ++c) {
      const double u = rows.value(i, c);
      if (!(u >= 0.0 && u < 1.0))
        throw py::value_error(indexed(name, rows, i) + " = " + rowText(rows, i, width) +
                              ": random numbers must lie in [0, 1)");
    }
  return rows;
}

size_t commonRowCount(std::initializer_list<std::pair<const char*, const ArrayRows*>> arguments) {
  const char* first = nullptr;
  size_t n = 1;
  for (const auto& [name, rows] : arguments) {
    if (rows->broadcasts()) continue;
    if (!first) {
      first = name;
      n = rows->rows();
    } else if (rows->rows() != n) {
      throw py::value_error(std::string(name) + " has " + std::to_string(rows->rows()) + " rows but " +
                            first + " has " + std::to_string(n) +
                            "; give both N rows, or one row to use for all");
    }
  }
  return n;
}

py::array_t<double> newArray(size_t rows, size_t width) {
  if (width == 0) return py::array_t<double>({py::ssize_t(rows)});
  return py::array_t<double>({py::ssize_t(rows), py::ssize_t(width)});
}

}  // namespace scatterlab::python
