// Piecewise-bilinear functions on the unit square, tabulated at the vertices of a regular
// rows x columns grid, with an optional dependence on up to two parameters tabulated on their
// own grids (linear interpolation between parameter slices, clamped outside). Two uses:
//  - Values: interpolation only (several channels may share the grid);
//  - Density: each slice normalised to integrate to 1 over [0, 1]^2, plus the warp that maps
//    uniform points of the square to points with that density and its exact inverse.
//
// The warp is the "Marginal2D" of Dupuy & Jakob 2018 (the RGL material database's own warps;
// docs/references.md, "RGL measured BRDFs"): the row coordinate y is drawn first from the
// piecewise-linear marginal (the interpolated row integrals), then x from the conditional at
// that continuous y (the two neighbouring rows, interpolated); each step inverts a linear
// density inside one grid interval (sampleLinear). The ORDER matters beyond the density: an
// RGL file tabulates its colour over the warp's input square, so a reader must reproduce this
// exact map, not just some sampler of the same density. Interpolating between parameter
// slices blends their (normalised) values and cumulative sums alike, which is the warp of the
// blended density because every quantity is linear in the values.
//
// Coordinates: a point is (x, y) = (column, row) / (columns - 1, rows - 1); sample() uses u.y
// for the row and u.x for the column.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "materials/core/math.h"
#include "materials/core/piecewise_bilinear.h"

namespace scatterlab {

class ParametricBilinear2D {
 public:
  enum class Mode { Values, Density };
  static constexpr size_t MaxParameters = 2;

  // Which parameter slices a query blends, with their weights (at most 2^MaxParameters).
  struct Blend {
    std::array<size_t, 1u << MaxParameters> slice{};
    std::array<double, 1u << MaxParameters> weight{};
    size_t count = 0;

    void add(size_t s, double w) {
      slice[count] = s;
      weight[count] = w;
      ++count;
    }
  };

  struct Warped {
    Vec2d point;     // in [0, 1]^2
    double density;  // of the warped point w.r.t. dx dy
  };

  ParametricBilinear2D() = default;

  // `data` is row-major [p_0]...[p_{n-1}][channel][row][column]; `parameterGrids` holds n <=
  // MaxParameters grids, each non-empty and strictly increasing. Values may be any finite
  // number; a Density needs one channel, non-negative values and a positive integral in every
  // slice. Throws std::invalid_argument saying what is wrong (the caller names the source).
  ParametricBilinear2D(std::span<const double> data, size_t rows, size_t columns, size_t channels,
                       std::vector<std::vector<double>> parameterGrids, Mode mode)
      : rows_(rows), columns_(columns), channels_(channels), grids_(std::move(parameterGrids)) {
    if (rows < 2 || columns < 2) throw std::invalid_argument("needs at least 2 x 2 grid points");
    if (channels < 1 || (mode == Mode::Density && channels != 1))
      throw std::invalid_argument("a density has exactly one channel, values at least one");
    if (grids_.size() > MaxParameters) throw std::invalid_argument("more than 2 parameters");
    size_t slices = 1;
    for (const auto& grid : grids_) {
      if (grid.empty()) throw std::invalid_argument("a parameter grid is empty");
      for (size_t i = 1; i < grid.size(); ++i)
        if (!(grid[i] > grid[i - 1]))
          throw std::invalid_argument("a parameter grid does not increase strictly");
      slices *= grid.size();
    }
    const size_t cells = rows * columns;
    if (data.size() != slices * channels * cells)
      throw std::invalid_argument(std::to_string(data.size()) + " values, expected " +
                                  std::to_string(slices * channels * cells));
    values_.assign(data.begin(), data.end());
    if (mode == Mode::Values) return;

    const double dx = 1.0 / double(columns - 1), dy = 1.0 / double(rows - 1);
    conditional_.resize(values_.size());
    rowTotals_.resize(slices * rows);
    marginal_.resize(slices * rows);
    for (size_t slice = 0; slice < slices; ++slice) {
      double* v = &values_[slice * cells];
      for (size_t i = 0; i < cells; ++i)
        if (!(v[i] >= 0)) throw std::invalid_argument("negative value in a density");
      // Integral of the bilinear interpolant over the unit square: trapezoids in both axes.
      double total = 0;
      for (size_t r = 0; r < rows; ++r) {
        double row = 0;
        for (size_t c = 0; c + 1 < columns; ++c)
          row += 0.5 * dx * (v[r * columns + c] + v[r * columns + c + 1]);
        total += (r == 0 || r + 1 == rows ? 0.5 : 1.0) * dy * row;
      }
      if (!(total > 0) || !std::isfinite(total))
        throw std::invalid_argument("slice " + std::to_string(slice) + " has no positive integral");
      for (size_t i = 0; i < cells; ++i) v[i] /= total;
      double* cdf = &conditional_[slice * cells];
      for (size_t r = 0; r < rows; ++r) {
        cdf[r * columns] = 0;
        for (size_t c = 0; c + 1 < columns; ++c)
          cdf[r * columns + c + 1] =
              cdf[r * columns + c] + 0.5 * dx * (v[r * columns + c] + v[r * columns + c + 1]);
        rowTotals_[slice * rows + r] = cdf[r * columns + columns - 1];
      }
      double* m = &marginal_[slice * rows];
      m[0] = 0;
      for (size_t r = 0; r + 1 < rows; ++r)
        m[r + 1] = m[r] + 0.5 * dy * (rowTotals_[slice * rows + r] + rowTotals_[slice * rows + r + 1]);
    }
  }

  size_t rows() const { return rows_; }
  size_t columns() const { return columns_; }
  size_t channels() const { return channels_; }
  const std::vector<std::vector<double>>& parameterGrids() const { return grids_; }

  // The slices and weights for `parameters` (one value per grid): per parameter, the grid
  // interval holding it (the first or last interval outside the grid) and the linear weight,
  // clamped to [0, 1]; a grid with one point contributes that slice with weight 1.
  Blend blend(std::span<const double> parameters) const {
    Blend b;
    b.count = 1;
    b.slice[0] = 0;
    b.weight[0] = 1.0;
    for (size_t d = 0; d < grids_.size(); ++d) {
      const auto& grid = grids_[d];
      size_t index = 0;
      double w1 = 0.0;
      if (grid.size() > 1) {
        const double p = parameters[d];
        const auto upper = std::upper_bound(grid.begin(), grid.end(), p);
        index =
            std::min<size_t>(size_t(std::max<std::ptrdiff_t>(upper - grid.begin() - 1, 0)), grid.size() - 2);
        w1 = std::clamp((p - grid[index]) / (grid[index + 1] - grid[index]), 0.0, 1.0);
      }
      Blend next;
      for (size_t k = 0; k < b.count; ++k) {
        const size_t base = b.slice[k] * grid.size() + index;
        if (1.0 - w1 > 0) next.add(base, b.weight[k] * (1.0 - w1));
        if (w1 > 0) next.add(base + 1, b.weight[k] * w1);
      }
      b = next;
    }
    return b;
  }

  // The interpolated value of `channel` at p (clamped to the square); a Density's is the
  // normalised density.
  double eval(const Vec2d& p, const Blend& b, size_t channel = 0) const {
    const Cell cell = locate(p);
    double result = 0;
    for (size_t k = 0; k < b.count; ++k) {
      const double* v = &values_[(b.slice[k] * channels_ + channel) * rows_ * columns_];
      const size_t i = cell.row * columns_ + cell.column;
      const double lower = (1 - cell.s) * v[i] + cell.s * v[i + 1];
      const double upper = (1 - cell.s) * v[i + columns_] + cell.s * v[i + columns_ + 1];
      result += b.weight[k] * ((1 - cell.t) * lower + cell.t * upper);
    }
    return result;
  }

  // A point with the (blended) density, from u in [0, 1]^2. Density mode only.
  Warped sample(Vec2d u, const Blend& b) const {
    constexpr double OneMinusEpsilon = 0x1.fffffffffffffp-1;
    u = glm::clamp(u, Vec2d(0.0), Vec2d(OneMinusEpsilon));
    const double dx = 1.0 / double(columns_ - 1), dy = 1.0 / double(rows_ - 1);
    // The row: the last r with marginal(r) <= u.y, then inside [r, r + 1] a linear density.
    const auto marginal = [&](size_t r) { return mix(marginal_, rows_, r, b); };
    size_t row = lastAtMost(rows_, u.y, marginal);
    const double m0 = marginal(row), m1 = marginal(row + 1);
    const double r0 = mix(rowTotals_, rows_, row, b), r1 = mix(rowTotals_, rows_, row + 1, b);
    const double t = sampleWithin(m1 > m0 ? (u.y - m0) / (m1 - m0) : u.y, r0, r1);
    // The column, from the conditional at that continuous row position.
    const size_t cells = rows_ * columns_;
    const auto conditional = [&](size_t c) {
      return (1 - t) * mix(conditional_, cells, row * columns_ + c, b) +
             t * mix(conditional_, cells, (row + 1) * columns_ + c, b);
    };
    const double target = u.x * ((1 - t) * r0 + t * r1);
    const size_t column = lastAtMost(columns_, target, conditional);
    const double c0 = conditional(column), c1 = conditional(column + 1);
    const size_t i = row * columns_ + column;
    const double g0 = (1 - t) * mix(values_, cells, i, b) + t * mix(values_, cells, i + columns_, b);
    const double g1 = (1 - t) * mix(values_, cells, i + 1, b) + t * mix(values_, cells, i + columns_ + 1, b);
    const double s = sampleWithin(c1 > c0 ? (target - c0) / (c1 - c0) : u.x, g0, g1);
    return {{(double(column) + s) * dx, (double(row) + t) * dy}, (1 - s) * g0 + s * g1};
  }

  // The u that sample() maps to p (clamped to the square), and the density at p. Density mode.
  Warped invert(const Vec2d& p, const Blend& b) const {
    const Cell cell = locate(p);
    const double dx = 1.0 / double(columns_ - 1), dy = 1.0 / double(rows_ - 1);
    const size_t cells = rows_ * columns_, i = cell.row * columns_ + cell.column;
    const double s = cell.s, t = cell.t;
    const double g0 = (1 - t) * mix(values_, cells, i, b) + t * mix(values_, cells, i + columns_, b);
    const double g1 = (1 - t) * mix(values_, cells, i + 1, b) + t * mix(values_, cells, i + columns_ + 1, b);
    const double r0 = mix(rowTotals_, rows_, cell.row, b), r1 = mix(rowTotals_, rows_, cell.row + 1, b);
    const double before =
        (1 - t) * mix(conditional_, cells, i, b) + t * mix(conditional_, cells, i + columns_, b);
    const double rowTotal = (1 - t) * r0 + t * r1;
    // Integrals of the linear densities up to s and t inside the cell.
    const double x = rowTotal > 0 ? (before + dx * s * (g0 + 0.5 * s * (g1 - g0))) / rowTotal : p.x;
    const double y = mix(marginal_, rows_, cell.row, b) + dy * t * (r0 + 0.5 * t * (r1 - r0));
    return {{std::clamp(x, 0.0, 1.0), std::clamp(y, 0.0, 1.0)}, (1 - s) * g0 + s * g1};
  }

 private:
  struct Cell {
    size_t row, column;
    double t, s;  // position inside the cell along rows (y) and columns (x), in [0, 1]
  };

  Cell locate(const Vec2d& p) const {
    const double x = std::clamp(p.x, 0.0, 1.0) * double(columns_ - 1);
    const double y = std::clamp(p.y, 0.0, 1.0) * double(rows_ - 1);
    const size_t column = std::min(size_t(x), columns_ - 2), row = std::min(size_t(y), rows_ - 2);
    return {row, column, y - double(row), x - double(column)};
  }

  // sum_k weight_k table[slice_k * stride + index]
  static double mix(const std::vector<double>& table, size_t stride, size_t index, const Blend& b) {
    double sum = 0;
    for (size_t k = 0; k < b.count; ++k) sum += b.weight[k] * table[b.slice[k] * stride + index];
    return sum;
  }

  // The last k in [0, n - 2] with cumulative(k) <= target (0 when none is).
  template <typename Cumulative>
  static size_t lastAtMost(size_t n, double target, const Cumulative& cumulative) {
    size_t lo = 0, hi = n - 1;
    while (hi - lo > 1) {
      const size_t mid = (lo + hi) / 2;
      (cumulative(mid) <= target ? lo : hi) = mid;
    }
    return lo;
  }

  // Inverse CDF of the density (1 - x) a + x b on [0, 1] (uniform when both are 0).
  static double sampleWithin(double u, double a, double b) {
    u = std::clamp(u, 0.0, 0x1.fffffffffffffp-1);
    return a + b > 0 ? sampleLinear(u, a, b) : u;
  }

  size_t rows_ = 0, columns_ = 0, channels_ = 0;
  std::vector<std::vector<double>> grids_;
  std::vector<double> values_;       // normalised for a Density
  std::vector<double> conditional_;  // Density: per row, the integral over x up to each column
  std::vector<double> rowTotals_;    // Density: per slice and row, the row's integral over x
  std::vector<double> marginal_;     // Density: per slice, the integral over y up to each row
};

}  // namespace scatterlab
