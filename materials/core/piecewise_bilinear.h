// A continuous 2-D density on a rectilinear grid: the bilinear interpolation of non-negative
// values at the grid's vertices, normalised. Sampled exactly by inversion: the marginal in x
// is piecewise linear (the row integrals, interpolated), the conditional in y at the sampled
// x is piecewise linear too (the two neighbouring rows, interpolated), and inside a linear
// piece the inverse CDF is a root of a quadratic (Jakob's "Marginal2D" warp in Mitsuba 2/3
// and pbrt-v4's PiecewiseLinear2D follow the same construction; the stable quadratic root is
// pbrt-v4's SampleLinear, Pharr, Jakob & Humphreys, 4th ed., sec. A.4.1).
//
// Unlike a piecewise-constant table, the density is continuous, so quadrature of it (the
// chi-square kit's expected counts) converges fast, and there is no jump for a sample to
// straddle.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <vector>

#include "materials/core/math.h"
#include "materials/core/piecewise_constant.h"

namespace scatterlab {

// x in [0, 1] with density proportional to (1 - x) a + x b, a, b >= 0, not both 0, from u in
// [0, 1): the root of the quadratic CDF in the form that does not cancel.
inline double sampleLinear(double u, double a, double b) {
  if (u == 0 && a == 0) return 0.0;
  const double x = u * (a + b) / (a + std::sqrt((1.0 - u) * a * a + u * b * b));
  return std::min(x, 0x1.fffffffffffffp-1);
}

class PiecewiseBilinear2D {
 public:
  PiecewiseBilinear2D() = default;
  // Edges strictly increasing (at least 2 each); values at the (xEdges.size() x
  // yEdges.size()) vertices, x-major: values[i * yEdges.size() + j] at (xEdges[i], yEdges[j]).
  PiecewiseBilinear2D(std::vector<double> xEdges, std::vector<double> yEdges, std::vector<double> values)
      : x_(std::move(xEdges)), y_(std::move(yEdges)), v_(std::move(values)) {
    const size_t nx = x_.size(), ny = y_.size();
    if (nx < 2 || ny < 2 || v_.size() != nx * ny)
      throw std::invalid_argument("PiecewiseBilinear2D: needs >= 2 edges per axis and one value per vertex");
    for (double value : v_)
      if (!(value >= 0) || !std::isfinite(value))
        throw std::invalid_argument("PiecewiseBilinear2D: values must be finite and non-negative");
    // Cumulative integral of each row's piecewise-linear function over y.
    cumulative_.resize(nx * ny);
    for (size_t i = 0; i < nx; ++i) {
      double sum = 0;
      cumulative_[i * ny] = 0;
      for (size_t j = 0; j + 1 < ny; ++j) {
        sum += 0.5 * (y_[j + 1] - y_[j]) * (value(i, j) + value(i, j + 1));
        cumulative_[i * ny + j + 1] = sum;
      }
    }
    std::vector<double> cellMass(nx - 1);
    for (size_t i = 0; i + 1 < nx; ++i)
      cellMass[i] = 0.5 * (x_[i + 1] - x_[i]) * (rowIntegral(i) + rowIntegral(i + 1));
    marginal_ = PiecewiseConstant1D(cellMass);
  }

  // Integral of the interpolated values (before normalisation); 0 means nothing to sample.
  double total() const { return marginal_.total(); }

  // Normalised density at (x, y) w.r.t. dx dy; 0 outside the grid or when total() is 0.
  double density(double x, double y) const {
    if (!(total() > 0) || x < x_.front() || x > x_.back() || y < y_.front() || y > y_.back()) return 0.0;
    const size_t i = cellOf(x_, x), j = cellOf(y_, y);
    const double t = (x - x_[i]) / (x_[i + 1] - x_[i]), s = (y - y_[j]) / (y_[j + 1] - y_[j]);
    const double lower = (1 - s) * value(i, j) + s * value(i, j + 1);
    const double upper = (1 - s) * value(i + 1, j) + s * value(i + 1, j + 1);
    return ((1 - t) * lower + t * upper) / total();
  }

  // A point with density density(x, y), from u in [0, 1)^2; needs total() > 0.
  Vec2d sample(const Vec2d& u) const {
    const size_t ny = y_.size();
    const auto cell = marginal_.sample(u.x);
    const size_t i = cell.cell;
    const double t = sampleLinear(cell.remapped, rowIntegral(i), rowIntegral(i + 1));
    const double x = x_[i] + t * (x_[i + 1] - x_[i]);
    // The conditional over y at x: rows i and i + 1 interpolated, cumulative sums likewise.
    const auto cumulative = [&](size_t j) {
      return (1 - t) * cumulative_[i * ny + j] + t * cumulative_[(i + 1) * ny + j];
    };
    const double target = u.y * cumulative(ny - 1);
    size_t lo = 0, hi = ny - 1;  // the last j with cumulative(j) <= target, j < ny - 1
    while (hi - lo > 1) {
      const size_t mid = (lo + hi) / 2;
      (cumulative(mid) <= target ? lo : hi) = mid;
    }
    const double g0 = (1 - t) * value(i, lo) + t * value(i + 1, lo);
    const double g1 = (1 - t) * value(i, lo + 1) + t * value(i + 1, lo + 1);
    const double mass = cumulative(lo + 1) - cumulative(lo);
    const double within = mass > 0 ? std::clamp((target - cumulative(lo)) / mass, 0.0, 1.0) : u.y;
    const double s = g0 + g1 > 0 ? sampleLinear(std::min(within, 0x1.fffffffffffffp-1), g0, g1) : within;
    return {x, y_[lo] + s * (y_[lo + 1] - y_[lo])};
  }

 private:
  double value(size_t i, size_t j) const { return v_[i * y_.size() + j]; }
  double rowIntegral(size_t i) const { return cumulative_[i * y_.size() + y_.size() - 1]; }
  // The cell [edges[k], edges[k + 1]] holding z (z inside the edges).
  static size_t cellOf(const std::vector<double>& edges, double z) {
    const auto it = std::upper_bound(edges.begin(), edges.end(), z);
    return std::min<size_t>(size_t(std::max<std::ptrdiff_t>(it - edges.begin() - 1, 0)), edges.size() - 2);
  }

  std::vector<double> x_, y_, v_;
  std::vector<double> cumulative_;  // per row, over y
  PiecewiseConstant1D marginal_;    // over x cells
};

}  // namespace scatterlab
