#include "validation/radial_chi_square.h"

#include <limits>

#include <tbb/parallel_for.h>

#include "materials/core/quadrature.h"

namespace scatterlab {

std::vector<double> equalProbabilityEdges(const std::function<double(double)>& quantile, int bins) {
  std::vector<double> edges{0.0};
  for (int k = 1; k < bins; ++k) edges.push_back(quantile(double(k) / bins));
  edges.push_back(std::numeric_limits<double>::infinity());
  return edges;
}

double integrateRadialDensity(const std::function<double(double)>& pdf, double a, double b, double far) {
  if (!std::isfinite(b)) b = std::max(far, a);
  if (a == 0.0) a = 1e-14 * b;
  if (!(b > a)) return 0.0;
  QuadratureOptions options;
  options.relativeTolerance = 1e-9;
  options.absoluteTolerance = 1e-15;
  options.minDepth = 4;
  options.maxDepth = 30;
  return adaptiveSimpson(
      [&](double t) {
        const double r = std::exp(t);
        return pdf(r) * r;
      },
      std::log(a), std::log(b), options);
}

double integrateAlongQuantiles(const std::function<double(double)>& f,
                               const std::function<double(double)>& quantile) {
  const std::vector<double> edges = equalProbabilityEdges(quantile, 8);
  const double far = quantile(1.0 - 1e-12);
  double sum = 0.0;
  for (size_t k = 0; k + 1 < edges.size(); ++k) sum += integrateRadialDensity(f, edges[k], edges[k + 1], far);
  return sum;
}

std::vector<double> radialExpectedCounts(const std::function<double(double)>& pdf,
                                         const std::vector<double>& edges, double far, size_t sampleCount) {
  const int bins = int(edges.size()) - 1;
  std::vector<double> expected(size_t(bins), 0.0);
  tbb::parallel_for(0, bins, [&](int b) {
    expected[size_t(b)] =
        double(sampleCount) * integrateRadialDensity(pdf, edges[size_t(b)], edges[size_t(b) + 1], far);
  });
  return expected;
}

}  // namespace scatterlab
