// A discrete distribution over the cells of a rows x columns grid: a row from the marginal
// distribution of the row sums (inverting its cumulative distribution, PiecewiseConstant1D),
// then a column from that row's conditional distribution by the alias method (AliasTable:
// one memory access, where inversion would read log2(columns) entries of a row that is
// usually out of cache; pbrt-v4's PiecewiseConstant2D inverts both, Pharr, Jakob & Humphreys,
// "Physically Based Rendering", 4th ed., sec. A.5.3). The leftover of each uniform number is
// returned rescaled to [0, 1), uniform within the chosen cell, to place the point inside it.
// Cells of zero weight are never chosen. The caller owns the cells' geometry: this class only
// knows their probabilities, so a cell's density is probability / (the cell's measure).
#pragma once

#include <span>
#include <stdexcept>
#include <vector>

#include "materials/core/alias_table.h"
#include "materials/core/math.h"
#include "materials/core/piecewise_constant.h"

namespace scatterlab {

class PiecewiseConstant2D {
 public:
  PiecewiseConstant2D() = default;
  // weights[row * columns + column], finite and >= 0; all zero gives an empty distribution
  // (total() == 0).
  PiecewiseConstant2D(std::span<const double> weights, size_t rows, size_t columns)
      : rows_(rows), columns_(columns), weights_(weights.begin(), weights.end()) {
    if (rows == 0 || columns == 0 || weights.size() != rows * columns)
      throw std::invalid_argument("PiecewiseConstant2D: needs rows * columns > 0 weights");
    rowSums_.resize(rows);
    slots_.resize(rows * columns);
    std::vector<AliasTable::Slot> row;
    for (size_t r = 0; r < rows; ++r) {
      AliasTable table;
      rowSums_[r] = table.build(weights.subspan(r * columns, columns), row);
      std::copy(row.begin(), row.end(), slots_.begin() + std::ptrdiff_t(r * columns));
    }
    marginal_ = PiecewiseConstant1D(rowSums_);
  }

  size_t rows() const { return rows_; }
  size_t columns() const { return columns_; }
  double total() const { return marginal_.total(); }

  // Probability of cell (row, column); 0 for an empty distribution.
  double probability(size_t row, size_t column) const {
    return rowSums_[row] > 0 ? marginal_.probability(row) * weights_[row * columns_ + column] / rowSums_[row]
                             : 0.0;
  }

  struct Sample {
    size_t row, column;
    Vec2d remapped;  // (row leftover, column leftover), each in [0, 1): where u fell in the cell
  };
  // u in [0, 1)^2 (u.x picks the row, u.y the column); needs total() > 0. The cell's
  // probability is probability(row, column).
  Sample sample(const Vec2d& u) const {
    const auto row = marginal_.sample(u.x);
    const auto column = AliasTable::sampleSlots(slots_.data() + row.cell * columns_, columns_, u.y);
    return {row.cell, column.cell, {row.remapped, column.remapped}};
  }

 private:
  size_t rows_ = 0, columns_ = 0;
  std::vector<double> weights_, rowSums_;
  PiecewiseConstant1D marginal_;         // over rows
  std::vector<AliasTable::Slot> slots_;  // each row's alias table, row-major
};

}  // namespace scatterlab
