// Solving g(x) = target for a non-decreasing g on a bracket [lo, hi], the step every inverse
// CDF and every "find the albedo that gives this reflectance" inversion needs.
//
//  - solveIncreasing: Newton's method safeguarded by bisection (Press et al., Numerical
//    Recipes, 3rd ed., section 9.4, rtsafe): a Newton step that leaves the shrinking bracket
//    is replaced by bisection, so it converges for any monotone g and quadratically near a
//    simple root. Needs g and its derivative.
//  - bisectIncreasing: bisection alone, for functions without a derivative (tabulated ones).
// Both return x with the bracket (or the last step) narrower than xTolerance, and clamp to
// [lo, hi] when the target lies outside g's range there.
#pragma once

#include <algorithm>
#include <cmath>

namespace scatterlab {

struct ValueAndSlope {
  double value = 0.0;
  double slope = 0.0;  // dg/dx
};

// `g(x) -> ValueAndSlope`; `initial` is the first Newton iterate (clamped into the bracket).
template <typename G>
double solveIncreasing(const G& g, double target, double lo, double hi, double initial, double xTolerance) {
  double x = std::clamp(initial, lo, hi);
  for (int iteration = 0; iteration < 200; ++iteration) {
    const ValueAndSlope v = g(x);
    const double excess = v.value - target;
    if (excess == 0.0) return x;
    if (excess > 0)
      hi = x;
    else
      lo = x;
    if (v.slope > 0) {
      const double newton = x - excess / v.slope;
      // Tested before the bracket: a converged step may land on the bracket's end.
      if (std::abs(newton - x) <= xTolerance) return std::clamp(newton, lo, hi);
      x = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
    } else {
      x = 0.5 * (lo + hi);
    }
    if (hi - lo <= xTolerance) return 0.5 * (lo + hi);
  }
  return x;
}

// `g(x) -> double`, non-decreasing on [lo, hi].
template <typename G>
double bisectIncreasing(const G& g, double target, double lo, double hi, double xTolerance) {
  for (int iteration = 0; iteration < 200 && hi - lo > xTolerance; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    if (g(mid) < target)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace scatterlab
