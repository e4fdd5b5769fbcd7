// The numpy arrays the materials API takes (docs/python.md, "Arrays"), checked once at the
// boundary so the C++ loops behind it never see a wrong shape, type or value: float64 only (a
// float32 direction would be silently rounded), rows of directions of unit length, random
// numbers in [0, 1). Every error is a ValueError naming the argument, the row and what is
// allowed.
#pragma once

#include <cstddef>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "materials/core/math.h"

namespace scatterlab::python {

// Rows of a C-contiguous float64 array: (N, width), or (N,) for width 1. A single row given
// without its N axis ((3,) for a direction) is one row that broadcasts against any N.
class ArrayRows {
 public:
  ArrayRows() = default;
  ArrayRows(pybind11::array_t<double, pybind11::array::c_style> array, size_t rows, size_t width,
            bool broadcasts)
      : array_(std::move(array)), data_(array_.data()), rows_(rows), width_(width), broadcasts_(broadcasts) {}

  size_t rows() const { return rows_; }
  bool broadcasts() const { return broadcasts_; }
  double value(size_t row, size_t column = 0) const {
    return data_[(broadcasts_ ? 0 : row) * width_ + column];
  }
  Vec3d direction(size_t row) const { return {value(row, 0), value(row, 1), value(row, 2)}; }
  Vec2d pair(size_t row) const { return {value(row, 0), value(row, 1)}; }

 private:
  pybind11::array_t<double, pybind11::array::c_style> array_;
  const double* data_ = nullptr;
  size_t rows_ = 0, width_ = 0;
  bool broadcasts_ = false;
};

// Unit directions: (N, 3) or one (3,); finite, |w| = 1 within UnitLengthTolerance.
ArrayRows directionArgument(pybind11::handle value, const char* name);
// Random numbers in [0, 1): (N,) or (N, 2) by `width`; a scalar for width 1 broadcasts.
ArrayRows unitIntervalArgument(pybind11::handle value, const char* name, size_t width);

// The N the arguments agree on (those that broadcast fit any N); ValueError naming the two that
// disagree otherwise.
size_t commonRowCount(std::initializer_list<std::pair<const char*, const ArrayRows*>> arguments);

// A fresh float64 array of shape (rows, width), or (rows,) for width 0.
pybind11::array_t<double> newArray(size_t rows, size_t width);

}  // namespace scatterlab::python
