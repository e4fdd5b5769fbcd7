// PiecewiseCubic1D: interpolates its nodes, reproduces quadratics exactly (Bessel's slopes are
// a parabola's), equals Catmull-Rom on uniform nodes, converges as h^3, and rejects bad nodes.
#include "materials/core/piecewise_cubic.h"

#include <gtest/gtest.h>

#include <cmath>

#include "materials/core/catmull_rom.h"

namespace scatterlab {
namespace piecewise_cubic_test {

TEST(PiecewiseCubic1D, InterpolatesTheNodesAndReproducesQuadratics) {
  const std::vector<double> x{0.0, 0.1, 0.35, 0.4, 0.9, 1.7};
  std::vector<double> y;
  const auto quadratic = [](double t) { return 2.0 - 3.0 * t + 1.25 * t * t; };
  for (const double t : x) y.push_back(quadratic(t));
  const PiecewiseCubic1D f(x, y);
  for (size_t i = 0; i < x.size(); ++i) EXPECT_DOUBLE_EQ(f(x[i]), y[i]);
  for (double t = 0.0; t <= 1.7; t += 0.01) EXPECT_NEAR(f(t), quadratic(t), 1e-13) << t;
  // Clamped to the range.
  EXPECT_DOUBLE_EQ(f(-1.0), y.front());
  EXPECT_DOUBLE_EQ(f(5.0), y.back());
}

TEST(PiecewiseCubic1D, IsCatmullRomOnUniformNodes) {
  std::vector<double> x, y;
  for (int i = 0; i <= 10; ++i) {
    x.push_back(i / 10.0);
    y.push_back(std::sin(3.0 * i / 10.0) + 0.1 * i * i);
  }
  const PiecewiseCubic1D f(x, y);
  const CatmullRomTable2D catmullRom(1, 11, y);
  // Interior intervals (Catmull-Rom's phantom end nodes continue the end parabola too).
  for (double t = 0.0; t <= 1.0; t += 0.013) EXPECT_NEAR(f(t), catmullRom(0.0, t), 1e-14) << t;
}

// Halving the spacing of non-uniform nodes divides the error of a smooth function by ~8.
TEST(PiecewiseCubic1D, ConvergesAsTheCubeOfTheSpacing) {
  const auto error = [](int n) {
    std::vector<double> x, y;
    for (int i = 0; i <= n; ++i) {
      const double t = double(i) / n;
      x.push_back(t * t * 2.0);  // denser near 0
      y.push_back(std::exp(-x.back()) * std::cos(2.0 * x.back()));
    }
    const PiecewiseCubic1D f(x, y);
    double worst = 0.0;
    for (double t = 0.0; t <= 2.0; t += 1e-3)
      worst = std::max(worst, std::abs(f(t) - std::exp(-t) * std::cos(2.0 * t)));
    return worst;
  };
  const double coarse = error(40), fine = error(80);
  EXPECT_GT(coarse / fine, 6.0);
  EXPECT_LT(coarse / fine, 20.0);
  EXPECT_LT(fine, 1e-4);
}

TEST(PiecewiseCubic1D, RejectsTooFewOrUnsortedNodes) {
  EXPECT_THROW(PiecewiseCubic1D({0.0, 1.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(PiecewiseCubic1D({0.0, 1.0, 1.0}, {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(PiecewiseCubic1D({0.0, 1.0, 2.0}, {1.0, 2.0}), std::invalid_argument);
}

}  // namespace piecewise_cubic_test
}  // namespace scatterlab
