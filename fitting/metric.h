// Error metrics of BRDF fits and robust losses (docs/references.md, "Ngan et al. 2005 models and
// fitting metrics"). A metric compares a measured value f with the model's value m at a
// direction pair (wi, wo) through a transform g and a weight w:
//   residual = sqrt(w(theta_i, theta_o)) (g(f, cos theta_i) - g(m, cos theta_i)),
// and the fit minimises the sum of squared residuals over the samples and channels:
//   l2         g = f,                       w = 1                   (plain L2 on f)
//   ngan       g = f cos theta_i,           w = sin theta_i sin theta_o
//                                           (Ngan et al. 2005, cosine-weighted L2)
//   low-l2     g = f cos theta_i,           w = sin theta_i         (Low et al. 2012, E1)
//   low-log    g = ln(1 + f cos theta_i),   w = sin theta_i         (Low et al. 2012, E2)
//   cube-root  g = (f cos theta_i + eps)^(1/3), w = sin theta_i sin theta_o
//              (Fores, Ferwerda & Gu 2012: cube roots of the cosine-weighted values, with
//              Ngan's weights; eps = 1e-6 sr^-1 keeps the derivative finite where m = 0)
// The metrics are not symmetric in wi and wo, while a MERL cell stands for both orderings of
// its pair (reciprocity), so each sample counts both orderings with weight 1/2 each. For the
// metrics with g linear in f the two collapse into one residual with the mean weight.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <ceres/loss_function.h>

#include "materials/core/math.h"

namespace scatterlab::fitting {

enum class Metric { L2, Ngan, LowL2, LowLog, CubeRoot };

std::string toString(Metric metric);
// Nothing when the name is not a metric.
std::optional<Metric> parseMetric(std::string_view name);
std::vector<std::string> metricNames();
// One line per metric for --help and the README.
std::string describe(Metric metric);

inline constexpr double CubeRootOffset = 1e-6;

// g(f, c) with c = cos theta of the ordering's incident direction, and dg/df.
inline double metricTransform(Metric metric, double f, double cosIn) {
  switch (metric) {
    case Metric::L2: return f;
    case Metric::Ngan:
    case Metric::LowL2: return f * cosIn;
    case Metric::LowLog: return std::log1p(std::max(f * cosIn, -0.5));
    case Metric::CubeRoot: return std::cbrt(std::max(f * cosIn, 0.0) + CubeRootOffset);
  }
  return f;
}
inline double metricSlope(Metric metric, double f, double cosIn) {
  switch (metric) {
    case Metric::L2: return 1.0;
    case Metric::Ngan:
    case Metric::LowL2: return cosIn;
    case Metric::LowLog: return cosIn / (1.0 + std::max(f * cosIn, -0.5));
    case Metric::CubeRoot: {
      const double root = std::cbrt(std::max(f * cosIn, 0.0) + CubeRootOffset);
      return cosIn / (3.0 * root * root);
    }
  }
  return 1.0;
}
// w for an ordering whose incident and outgoing directions have these polar sines.
inline double metricWeight(Metric metric, double sinIn, double sinOut) {
  switch (metric) {
    case Metric::L2: return 1.0;
    case Metric::Ngan:
    case Metric::CubeRoot: return sinIn * sinOut;
    case Metric::LowL2:
    case Metric::LowLog: return sinIn;
  }
  return 1.0;
}
// True when g is f times a factor of the geometry: the residual is then linear in the model
// value, the two orderings merge, and the linear scales have a closed-form solution.
inline bool isLinear(Metric metric) {
  return metric == Metric::L2 || metric == Metric::Ngan || metric == Metric::LowL2;
}
// The linear metric whose closed-form scales start a fit in `metric` (itself if linear).
Metric linearAnalogue(Metric metric);

// Robust losses of the residuals (Ceres's loss functions rho(s), s = residual^2).
enum class RobustLoss { None, Huber, Cauchy, SoftL1 };
std::string toString(RobustLoss loss);
std::optional<RobustLoss> parseRobustLoss(std::string_view name);
std::vector<std::string> robustLossNames();
// The Ceres loss with scale `scale` (in residual units); nullptr for None.
std::unique_ptr<ceres::LossFunction> makeLossFunction(RobustLoss loss, double scale);

}  // namespace scatterlab::fitting
