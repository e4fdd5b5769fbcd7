// The 2-D planar chi-square kit on the uniform disk (concentric mapping, warp.h).
#include <gtest/gtest.h>

#include "materials/core/warp.h"
#include "validation/planar_chi_square.h"

namespace scatterlab {
namespace planar_chi_square_test {

const double Threshold = sidakSignificance(0.01, 3);

PolarGrid diskGrid() {
  PolarGrid grid;
  for (int k = 0; k <= 12; ++k) grid.ringEdges.push_back(std::sqrt(k / 12.0));  // equal areas
  grid.sectors = 24;
  return grid;
}

PlanarChiSquareOptions options() {
  PlanarChiSquareOptions o;
  o.sampleCount = 200000;
  o.seed = 4;
  o.threshold = Threshold;
  return o;
}

auto diskSampler(double scale) {
  return [scale](CounterRng& rng) -> std::optional<Vec2d> {
    return scale * sampleConcentricDisk(rng.uniform2D());
  };
}

TEST(PlanarChiSquare, AcceptsTheUniformDisk) {
  const ChiSquareResult r = planarChiSquareTest(
      diskSampler(1.0), [](const Vec2d& p) { return glm::length(p) < 1 ? InvPi : 0.0; }, diskGrid(),
      options());
  EXPECT_TRUE(r.passed) << r.statistic << " " << r.dof << " " << r.pValue << " " << r.failure;
}

TEST(PlanarChiSquare, RejectsADensityFivePercentHighOnHalfThePlane) {
  const ChiSquareResult r = planarChiSquareTest(
      diskSampler(1.0),
      [](const Vec2d& p) { return glm::length(p) < 1 ? InvPi * (p.x > 0 ? 1.05 : 0.95) : 0.0; }, diskGrid(),
      options());
  EXPECT_FALSE(r.passed);
}

TEST(PlanarChiSquare, PointsBeyondTheOuterRingRejectAtOnce) {
  // Samples on a disk 2% larger than the density's support.
  const ChiSquareResult r = planarChiSquareTest(
      diskSampler(1.02), [](const Vec2d& p) { return glm::length(p) < 1 ? InvPi : 0.0; }, diskGrid(),
      options());
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.failure.find("pdf integrates to 0"), std::string::npos) << r.failure;
}

TEST(PlanarChiSquare, CellIndexCoversThePlane) {
  const PolarGrid grid = diskGrid();
  EXPECT_EQ(grid.cellIndex({0.0, 0.0}), grid.sectors / 2);  // ring 0, phi = 0
  EXPECT_EQ(grid.cellIndex({2.0, 0.0}), grid.outsideCell());
  EXPECT_EQ(grid.cellIndex({-0.99, -1e-9}), (grid.rings() - 1) * grid.sectors);
}

}  // namespace planar_chi_square_test
}  // namespace scatterlab
