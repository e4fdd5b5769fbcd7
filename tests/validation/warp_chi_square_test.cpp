// Each warp's sampler against its own pdf through the chi-square kit, and a deliberately
// mismatched pair to show the test has the power to reject.
#include <gtest/gtest.h>

#include "materials/core/warp.h"
#include "validation/chi_square.h"

namespace scatterlab {
namespace warp_chi_square_test {

// 6 tests in this file at family-wise 1%.
const double Threshold = sidakSignificance(0.01, 6);

ChiSquareOptions options(int thetaBins = 64, int phiBins = 128) {
  ChiSquareOptions o;
  o.grid = {thetaBins, phiBins};
  o.sampleCount = 500000;
  o.seed = 7;
  o.threshold = Threshold;
  return o;
}

template <typename Warp> auto drawWith(Warp warp, double pdf) {
  return [=](CounterRng& rng) -> std::optional<DirectionSample> {
    return DirectionSample{warp(rng.uniform2D()), pdf};
  };
}

TEST(WarpChiSquare, UniformSphere) {
  const auto r = sphericalChiSquareTest(
      drawWith(sampleUniformSphere, uniformSpherePdf()), [](const Vec3d&) { return uniformSpherePdf(); },
      options());
  EXPECT_TRUE(r.passed) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.pValue << " "
                        << r.failure;
}

TEST(WarpChiSquare, UniformHemisphere) {
  const auto r = sphericalChiSquareTest(
      drawWith(sampleUniformHemisphere, uniformHemispherePdf()),
      [](const Vec3d& w) { return w.z >= 0 ? uniformHemispherePdf() : 0.0; }, options(63, 127));
  EXPECT_TRUE(r.passed) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.pValue << " "
                        << r.failure;
}

TEST(WarpChiSquare, CosineHemisphere) {
  auto draw = [](CounterRng& rng) -> std::optional<DirectionSample> {
    const Vec3d w = sampleCosineHemisphere(rng.uniform2D());
    if (w.z <= 0) return std::nullopt;
    return DirectionSample{w, cosineHemispherePdf(w.z)};
  };
  const auto r = sphericalChiSquareTest(
      draw, [](const Vec3d& w) { return cosineHemispherePdf(w.z); }, options());
  EXPECT_TRUE(r.passed) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.pValue << " "
                        << r.failure;
}

TEST(WarpChiSquare, UniformCone) {
  // A narrow cone (half-angle 8 deg): much of it falls into a few cells near the pole.
  const double cosMax = std::cos(radians(8.0));
  auto draw = [=](CounterRng& rng) -> std::optional<DirectionSample> {
    return DirectionSample{sampleUniformCone(rng.uniform2D(), cosMax), uniformConePdf(cosMax)};
  };
  const auto r = sphericalChiSquareTest(
      draw, [=](const Vec3d& w) { return w.z >= cosMax ? uniformConePdf(cosMax) : 0.0; }, options(37, 71));
  EXPECT_TRUE(r.passed) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.pValue << " "
                        << r.failure;
}

TEST(WarpChiSquare, RejectsCosineSamplesAgainstUniformPdf) {
  auto draw = [](CounterRng& rng) -> std::optional<DirectionSample> {
    const Vec3d w = sampleCosineHemisphere(rng.uniform2D());
    return DirectionSample{w, uniformHemispherePdf()};
  };
  const auto r = sphericalChiSquareTest(
      draw, [](const Vec3d& w) { return w.z >= 0 ? uniformHemispherePdf() : 0.0; }, options());
  EXPECT_FALSE(r.passed);
}

TEST(WarpChiSquare, RejectsSamplesOutsideThePdfSupport) {
  // Uniform-sphere samples against a hemisphere pdf: half the samples where pdf = 0.
  const auto r = sphericalChiSquareTest(
      drawWith(sampleUniformSphere, uniformHemispherePdf()),
      [](const Vec3d& w) { return w.z >= 0 ? uniformHemispherePdf() : 0.0; }, options());
  EXPECT_FALSE(r.passed);
  EXPECT_FALSE(r.failure.empty());
}

}  // namespace warp_chi_square_test
}  // namespace scatterlab
