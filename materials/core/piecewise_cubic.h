// A function tabulated at non-uniform nodes, interpolated by a C1 piecewise cubic: on each
// interval the cubic Hermite polynomial through the two end values, with each node's slope
// that of the parabola through the node and its two neighbours (Bessel's slopes; de Boor, "A
// Practical Guide to Splines", 2001, chapter IV, eq. 19), and at the two ends the slope of
// the parabola through the last three nodes. Error O(h^3) for smooth data; on uniform nodes it
// is exactly Catmull-Rom (catmull_rom.h), whose central differences are Bessel's slopes there.
//
// For tables whose nodes are placed adaptively (where the function needs them), so that the
// spacing is not uniform in any closed-form coordinate; a lookup is a binary search.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace scatterlab {

class PiecewiseCubic1D {
 public:
  PiecewiseCubic1D() = default;
  // x strictly increasing, at least 3 nodes; one value per node.
  PiecewiseCubic1D(std::vector<double> x, std::vector<double> y) : x_(std::move(x)), y_(std::move(y)) {
    const size_t n = x_.size();
    if (n < 3 || y_.size() != n)
      throw std::invalid_argument("PiecewiseCubic1D: needs >= 3 nodes and one value each");
    for (size_t i = 0; i + 1 < n; ++i)
      if (!(x_[i + 1] > x_[i]))
        throw std::invalid_argument("PiecewiseCubic1D: nodes must be strictly increasing");
    slope_.resize(n);
    for (size_t i = 0; i < n; ++i) {
      // The parabola through nodes k - 1, k, k + 1 (k the interior node nearest i), differentiated at x_i.
      const size_t k = std::clamp<size_t>(i, 1, n - 2);
      const double h0 = x_[k] - x_[k - 1], h1 = x_[k + 1] - x_[k];
      const double d0 = (y_[k] - y_[k - 1]) / h0, d1 = (y_[k + 1] - y_[k]) / h1;
      const double curvature = (d1 - d0) / (h0 + h1);  // half the second derivative
      // The parabola's derivative is linear in x: d0 + curvature (2 x - x_{k-1} - x_k).
      slope_[i] = d0 + curvature * (2.0 * x_[i] - x_[k - 1] - x_[k]);
    }
  }

  size_t size() const { return x_.size(); }
  double node(size_t i) const { return x_[i]; }
  double value(size_t i) const { return y_[i]; }

  // The interpolant at x, clamped to the nodes' range.
  double operator()(double x) const {
    x = std::clamp(x, x_.front(), x_.back());
    const size_t i = intervalOf(x);
    const double h = x_[i + 1] - x_[i], t = (x - x_[i]) / h;
    // The cubic Hermite basis.
    const double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * y_[i] + (t3 - 2 * t2 + t) * h * slope_[i] +
           (-2 * t3 + 3 * t2) * y_[i + 1] + (t3 - t2) * h * slope_[i + 1];
  }

 private:
  // The interval [x_i, x_{i+1}] holding x (inside the range).
  size_t intervalOf(double x) const {
    const auto it = std::upper_bound(x_.begin(), x_.end(), x);
    return std::min<size_t>(size_t(std::max<std::ptrdiff_t>(it - x_.begin() - 1, 0)), x_.size() - 2);
  }

  std::vector<double> x_, y_, slope_;
};

}  // namespace scatterlab
