// A discrete distribution over the cells of a rows x columns grid, sampled by inversion: a
// row from the marginal distribution of the row sums, then a column from that row's
// conditional distribution (pbrt-v4's PiecewiseConstant2D, Pharr, Jakob & Humphreys, "Physically
// Based Rendering", 4th ed., sec. A.5.3). Both steps reuse PiecewiseConstant1D, so the leftover
// of each uniform number is returned rescaled to [0, 1) to place the point inside the cell.
// Cells of zero weight are never chosen. The caller owns the cells' geometry: this class only
// knows their probabilities, so a cell's density is probability / (the cell's measure).
#pragma once

#include <span>
#include <stdexcept>
#include <vector>

#include "materials/core/math.h"
#include "materials/core/piecewise_constant.h"

namespace scatterlab {

class PiecewiseConstant2D {
 public:
  PiecewiseConstant2D() = default;
  // weights[row * columns + column], finite and >= 0; all zero gives an empty distribution
  // (total() == 0).
  PiecewiseConstant2D(std::span<const double> weights, size_t rows, size_t columns) : columns_(columns) {
    if (rows == 0 || columns == 0 || weights.size() != rows * columns)
      throw std::invalid_argument("PiecewiseConstant2D: needs rows * columns > 0 weights");
    std::vector<double> rowSums(rows, 0.0);
    conditionals_.reserve(rows);
    for (size_t r = 0; r < rows; ++r) {
      conditionals_.emplace_back(weights.subspan(r * columns, columns));
      rowSums[r] = conditionals_.back().total();
    }
    marginal_ = PiecewiseConstant1D(rowSums);
  }

  size_t rows() const { return conditionals_.size(); }
  size_t columns() const { return columns_; }
  double total() const { return marginal_.total(); }

  // Probability of cell (row, column); 0 for an empty distribution.
  double probability(size_t row, size_t column) const {
    return marginal_.probability(row) * conditionals_[row].probability(column);
  }

  struct Sample {
    size_t row, column;
    Vec2d remapped;  // (row leftover, column leftover), each in [0, 1): where u fell in the cell
    double probability;
  };
  // u in [0, 1)^2 (u.x picks the row, u.y the column); needs total() > 0.
  Sample sample(const Vec2d& u) const {
    const auto row = marginal_.sample(u.x);
    const PiecewiseConstant1D& conditional = conditionals_[row.cell];
    const auto column = conditional.sample(u.y);
    return {row.cell, column.cell, {row.remapped, column.remapped},
            marginal_.probability(row.cell) * conditional.probability(column.cell)};
  }

 private:
  size_t columns_ = 0;
  PiecewiseConstant1D marginal_;                   // over rows
  std::vector<PiecewiseConstant1D> conditionals_;  // one per row, over its columns
};

}  // namespace scatterlab
