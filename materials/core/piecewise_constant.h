// A discrete distribution over cells, sampled by inverting the cumulative distribution, with
// the leftover of the uniform number rescaled to [0, 1) so that it can place the point inside
// the chosen cell (pbrt-v4's PiecewiseConstant1D, Pharr, Jakob & Humphreys, "Physically Based
// Rendering", 4th ed., sec. A.4.1). Cells of zero weight are never chosen.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <vector>

namespace scatterlab {

class PiecewiseConstant1D {
 public:
  PiecewiseConstant1D() = default;
  // Weights must be finite and >= 0; all zero gives an empty distribution (total() == 0).
  explicit PiecewiseConstant1D(std::span<const double> weights) : weights_(weights.begin(), weights.end()) {
    cdf_.resize(weights_.size() + 1, 0.0);
    for (size_t i = 0; i < weights_.size(); ++i) {
      if (!(weights_[i] >= 0) || !std::isfinite(weights_[i]))
        throw std::invalid_argument("PiecewiseConstant1D: weights must be finite and non-negative");
      cdf_[i + 1] = cdf_[i] + weights_[i];
    }
    total_ = cdf_.back();
    if (total_ > 0) {
      for (double& c : cdf_) c /= total_;
      cdf_.back() = 1.0;
    }
  }

  size_t size() const { return weights_.size(); }
  double total() const { return total_; }
  double weight(size_t i) const { return weights_[i]; }
  // Probability of cell i; 0 for an empty distribution.
  double probability(size_t i) const { return total_ > 0 ? weights_[i] / total_ : 0.0; }

  struct Sample {
    size_t cell;
    double remapped;  // where u fell inside the cell's share of [0, 1), in [0, 1)
  };
  // u in [0, 1); needs total() > 0.
  Sample sample(double u) const {
    // The last i with cdf[i] <= u: skips zero-weight cells, whose cdf entries repeat.
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u);
    const size_t i = std::min<size_t>(size_t(std::max<std::ptrdiff_t>(it - cdf_.begin() - 1, 0)), size() - 1);
    const double width = cdf_[i + 1] - cdf_[i];
    const double remapped = width > 0 ? (u - cdf_[i]) / width : 0.0;
    return {i, std::clamp(remapped, 0.0, OneMinusEpsilon)};
  }

 private:
  static constexpr double OneMinusEpsilon = 0x1.fffffffffffffp-1;

  std::vector<double> weights_, cdf_;
  double total_ = 0;
};

}  // namespace scatterlab
