// Gauss-Legendre rules on [0, 1]: a fixed-cost quadrature, exact for polynomials of degree
// 2n - 1, for integrals of smooth functions that are evaluated many times over (per-material
// tables built at construction), where the adaptive scheme of quadrature.h would cost too much.
#pragma once

#include <array>
#include <cmath>

#include "materials/core/math.h"

namespace scatterlab {

template <int N> struct GaussLegendreRule {
  std::array<double, N> nodes{}, weights{};  // on [0, 1]; the weights sum to 1
};

// Nodes by Newton's method on the Legendre polynomial P_N from Tricomi's estimate
// cos(pi (i + 3/4) / (N + 1/2)); weights 2 / ((1 - x^2) P_N'(x)^2) (Abramowitz & Stegun
// 25.4.29), mapped from [-1, 1] to [0, 1].
template <int N> const GaussLegendreRule<N>& gaussLegendre() {
  static const GaussLegendreRule<N> rule = [] {
    GaussLegendreRule<N> r;
    for (int i = 0; i < N; ++i) {
      double x = std::cos(Pi * (i + 0.75) / (N + 0.5)), derivative = 1.0;
      for (int iteration = 0; iteration < 100; ++iteration) {
        double p = 1.0, previous = 0.0;
        for (int k = 1; k <= N; ++k) {
          const double older = previous;
          previous = p;
          p = ((2.0 * k - 1.0) * x * previous - (k - 1.0) * older) / k;
        }
        derivative = N * (x * p - previous) / (x * x - 1.0);
        const double step = p / derivative;
        x -= step;
        if (std::abs(step) < 1e-16) break;
      }
      r.nodes[i] = 0.5 * (1.0 - x);
      r.weights[i] = 1.0 / ((1.0 - x * x) * derivative * derivative);
    }
    return r;
  }();
  return rule;
}

}  // namespace scatterlab
