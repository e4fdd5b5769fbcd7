// A continuous distribution given by its cumulative function at nodes: node values F_k
// (non-decreasing) and node densities f_k = F'(x_k) (>= 0), joined by cubic Hermite pieces.
// The densities are limited as Fritsch & Carlson (1980, "Monotone Piecewise Cubic
// Interpolation", SIAM J. Numer. Anal. 17(2), the sufficient square 0 <= f_k / secant <= 3 of
// both neighbouring intervals), so F stays monotone: its density F' is continuous and never
// negative, and the distribution is exactly what inversion samples. cumulative(), density()
// and invert() are the CDF / pdf / inverse triplet of one function, with no approximation
// between them; where the given densities need no limiting they are reproduced at the nodes.
//
// Values are unnormalised: total() = F_n - F_0 is whatever mass the table holds.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "materials/core/root_finding.h"

namespace scatterlab {

class MonotoneCubicCdf {
 public:
  MonotoneCubicCdf() = default;
  // x strictly increasing, F non-decreasing, f >= 0, all the same size (>= 2), finite.
  MonotoneCubicCdf(std::vector<double> x, std::vector<double> F, std::vector<double> f)
      : x_(std::move(x)), F_(std::move(F)), f_(std::move(f)) {
    const size_t n = x_.size();
    if (n < 2 || F_.size() != n || f_.size() != n)
      throw std::invalid_argument(
          "MonotoneCubicCdf needs at least two nodes and one value and density per node");
    for (size_t k = 0; k < n; ++k) {
      if (!std::isfinite(x_[k]) || !std::isfinite(F_[k]) || !(f_[k] >= 0) || !std::isfinite(f_[k]))
        throw std::invalid_argument(
            "MonotoneCubicCdf: nodes, values and densities must be finite, densities >= 0");
      if (k > 0 && (!(x_[k] > x_[k - 1]) || F_[k] < F_[k - 1]))
        throw std::invalid_argument("MonotoneCubicCdf: nodes must increase and values must not decrease");
    }
    for (size_t k = 0; k < n; ++k) {
      if (k > 0) f_[k] = std::min(f_[k], 3.0 * secant(k - 1));
      if (k + 1 < n) f_[k] = std::min(f_[k], 3.0 * secant(k));
    }
  }

  double total() const { return F_.back() - F_.front(); }
  double lower() const { return x_.front(); }
  double upper() const { return x_.back(); }
  const std::vector<double>& nodes() const { return x_; }

  // F(x): F_0 below the first node, F_n above the last.
  double cumulative(double x) const {
    if (x <= x_.front()) return F_.front();
    if (x >= x_.back()) return F_.back();
    const size_t k = interval(x);
    return piece(k, (x - x_[k]) / width(k));
  }

  // F'(x); 0 outside [x_0, x_n].
  double density(double x) const {
    if (x < x_.front() || x > x_.back()) return 0.0;
    const size_t k = interval(x);
    // >= 0 in exact arithmetic (the limited slopes); round-off can leave -1e-20 on a flat piece.
    return std::max(pieceSlope(k, (x - x_[k]) / width(k)) / width(k), 0.0);
  }

  // The x with F(x) = target, for target in [F_0, F_n] (clamped): Newton-bisection inside the
  // one interval whose values bracket the target, to 1e-15 of its width. Flat stretches
  // (zero mass) are never returned in their interior: the first x reaching the target is.
  double invert(double target) const {
    target = std::clamp(target, F_.front(), F_.back());
    // The first interval whose upper value reaches the target.
    const size_t upperNode = size_t(std::lower_bound(F_.begin() + 1, F_.end(), target) - F_.begin());
    const size_t k = std::min(upperNode, F_.size() - 1) - 1;
    const double t = solveIncreasing(
        [&](double s) {
          return ValueAndSlope{piece(k, s), pieceSlope(k, s)};
        },
        target, 0.0, 1.0, (target - F_[k]) / std::max(F_[k + 1] - F_[k], 1e-300), 1e-15);
    return x_[k] + t * width(k);
  }

 private:
  double width(size_t k) const { return x_[k + 1] - x_[k]; }
  double secant(size_t k) const { return (F_[k + 1] - F_[k]) / width(k); }
  size_t interval(double x) const {
    const size_t i = size_t(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin());
    return std::min(std::max<size_t>(i, 1), x_.size() - 1) - 1;
  }
  // The cubic of interval k at t in [0, 1] (Hermite basis) and its derivative in t.
  double piece(size_t k, double t) const {
    const double t2 = t * t, t3 = t2 * t, h = width(k);
    return (2 * t3 - 3 * t2 + 1) * F_[k] + (3 * t2 - 2 * t3) * F_[k + 1] + (t3 - 2 * t2 + t) * h * f_[k] +
           (t3 - t2) * h * f_[k + 1];
  }
  double pieceSlope(size_t k, double t) const {
    const double t2 = t * t, h = width(k);
    return (6 * t2 - 6 * t) * (F_[k] - F_[k + 1]) + (3 * t2 - 4 * t + 1) * h * f_[k] +
           (3 * t2 - 2 * t) * h * f_[k + 1];
  }

  std::vector<double> x_, F_, f_;
};

}  // namespace scatterlab
