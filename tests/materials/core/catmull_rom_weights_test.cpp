#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "materials/core/catmull_rom.h"

namespace scatterlab {
namespace catmull_rom_weights_test {

// Non-uniform nodes, denser toward 1 like the beam-diffusion albedo grid.
std::vector<double> nodes() {
  std::vector<double> x;
  for (int i = 0; i < 12; ++i) x.push_back((1.0 - std::exp(-3.0 * i / 11.0)) / (1.0 - std::exp(-3.0)));
  return x;
}

double interpolate(const std::vector<double>& x, const std::vector<double>& f, double at) {
  const CatmullRomWeights w = catmullRomWeights(x, at);
  double value = 0.0;
  for (int k = 0; k < 4; ++k) {
    const int i = w.offset + k;
    if (i >= 0 && i < int(x.size())) value += w.weight[k] * f[size_t(i)];
  }
  return value;
}

TEST(CatmullRomWeights, ReproduceNodeValuesAndSumToOne) {
  const std::vector<double> x = nodes();
  for (double at = 0.0; at <= 1.0; at += 0.0123) {
    const CatmullRomWeights w = catmullRomWeights(x, at);
    double sum = 0.0;
    for (int k = 0; k < 4; ++k)
      if (w.offset + k >= 0 && w.offset + k < int(x.size())) sum += w.weight[k];
    EXPECT_NEAR(sum, 1.0, 1e-14) << at;
  }
  std::vector<double> f;
  for (double xi : x) f.push_back(std::sin(3 * xi));
  for (size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(interpolate(x, f, x[i]), f[i], 1e-15);
}

TEST(CatmullRomWeights, ExactForLinearFunctions) {
  // The finite-difference slopes of a line are its slope, one-sided at the ends too.
  const std::vector<double> x = nodes();
  std::vector<double> f;
  for (double xi : x) f.push_back(2.0 - 3.0 * xi);
  for (double at = 0.0; at <= 1.0; at += 0.0171)
    EXPECT_NEAR(interpolate(x, f, at), 2.0 - 3.0 * at, 1e-14) << at;
}

TEST(CatmullRomWeights, ConvergeOnASmoothFunction) {
  const std::vector<double> x = nodes();
  std::vector<double> f;
  for (double xi : x) f.push_back(std::exp(xi));
  // The finite-difference slopes are not centred on non-uniform nodes, so they are first order:
  // the error is O(h^2 f''), ~6e-3 where the nodes are coarsest (h = 0.27) and 1e-3 where fine.
  for (double at = 0.05; at <= 0.95; at += 0.0371)
    EXPECT_NEAR(interpolate(x, f, at), std::exp(at), at < 0.3 ? 1e-2 : 3e-3) << at;
}

}  // namespace catmull_rom_weights_test
}  // namespace scatterlab
