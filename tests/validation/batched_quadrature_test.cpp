// The level-by-level quadrature (validation/batched_quadrature.h) against the depth-first one
// (materials/core/quadrature.h, validation/chi_square.h): the same numbers bit for bit, so that a
// model asked for its values in bulk (a BSDF written in Python) gets exactly the rows of a model
// asked one value at a time.
#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <vector>

#include "materials/bsdf/rough_dielectric.h"
#include "validation/batched_quadrature.h"
#include "validation/bsdf_check.h"
#include "validation/bsdf_sampling.h"
#include "validation/bulk_evaluated_bsdf.h"
#include "validation/energy.h"

namespace scatterlab {
namespace batched_quadrature_test {

// A peak narrow enough that adaptive Simpson refines many levels around it, on a smooth floor.
double peaked(double x) { return 0.2 + std::exp(-std::pow((x - 0.3137) / 1e-3, 2)); }

TEST(BatchedQuadrature, OneDimensionalIntegralsEqualTheDepthFirstOnesBitForBit) {
  QuadratureOptions shallow;
  shallow.maxDepth = 6;  // stops refining before the tolerance is met: the maxDepth branch
  QuadratureOptions noMinimum;
  noMinimum.minDepth = 0;
  const std::vector<BatchedInterval> intervals{
      {0.0, 1.0, QuadratureOptions{}}, {0.25, 0.5, shallow}, {-1.0, 2.0, noMinimum}, {0.3, 0.3137, {}}};
  int calls = 0;
  const auto results =
      adaptiveSimpsonBatched<double>(std::span<const BatchedInterval>(intervals),
                                     [&](std::span<const BatchedPoint> points, std::span<double> out) {
                                       ++calls;
                                       for (size_t i = 0; i < points.size(); ++i)
                                         out[i] = peaked(points[i].x);
                                     });
  ASSERT_EQ(results.size(), intervals.size());
  for (size_t k = 0; k < intervals.size(); ++k) {
    const QuadratureEstimate<double> expected =
        adaptiveSimpsonEstimate(peaked, intervals[k].a, intervals[k].b, intervals[k].options);
    EXPECT_EQ(results[k].value, expected.value) << "interval " << k;
    EXPECT_EQ(results[k].error, expected.error) << "interval " << k;
  }
  // One call for the first level of every interval, then one per refinement level: never more
  // than the deepest refinement allows.
  EXPECT_LE(calls, QuadratureOptions{}.maxDepth + 2);
}

TEST(BatchedQuadrature, TwoDimensionalIntegralsEqualTheDepthFirstOnesBitForBit) {
  const auto f = [](double x, double y) {
    return glm::dvec2(peaked(x) * (1.0 + y * y), std::exp(-std::pow((x + y - 0.4) / 2e-3, 2)));
  };
  const std::vector<BatchedRectangle> rectangles{
      {0.0, 1.0, 0.0, 0.5}, {0.3, 0.32, -0.1, 0.3}, {-1.0, 0.0, 0.0, 2.0}};
  QuadratureOptions options;
  options.absoluteTolerance = 1e-9;
  const auto results =
      adaptiveSimpson2DBatched<glm::dvec2>(std::span<const BatchedRectangle>(rectangles), options,
                                           [&](std::span<const Vec2d> xy, std::span<glm::dvec2> out) {
                                             for (size_t i = 0; i < xy.size(); ++i)
                                               out[i] = f(xy[i].x, xy[i].y);
                                           });
  for (size_t k = 0; k < rectangles.size(); ++k) {
    const BatchedRectangle& r = rectangles[k];
    const QuadratureEstimate<glm::dvec2> expected =
        adaptiveSimpson2DEstimate(f, r.x0, r.x1, r.y0, r.y1, options);
    EXPECT_EQ(results[k].value, expected.value) << "rectangle " << k;
    EXPECT_EQ(results[k].error, expected.error) << "rectangle " << k;
  }
}

// A rough dielectric at normal incidence: a narrow refracted lobe at the pole, where cellPieces
// cuts the pole cell geometrically, and a reflected one.
const RoughDielectricBsdf<GgxDistribution<double>>& dielectric() {
  static const RoughDielectricBsdf<GgxDistribution<double>> model(GgxDistribution<double>(0.05, 0.05), 1.5);
  return model;
}

TEST(BatchedQuadrature, CellIntegralsEqualTheDepthFirstOnesBitForBit) {
  const SphericalGrid grid{16, 32};
  const Vec3d wi = directionFromDegrees(0.5, 30);
  const SampleHistogram histogram =
      drawSamples(grid, bsdfDirectionSampler(dielectric(), wi, TransportMode::Importance), 20000, 7);
  const QuadratureOptions options;
  const auto integrand = bsdfEnergyIntegrand(dielectric(), wi, TransportMode::Importance);
  const CellIntegrals<glm::dvec4> expected =
      integrateCellsWithError(grid, integrand, histogram.probes, options);
  const CellIntegrals<glm::dvec4> batched = integrateCellsInBatches<glm::dvec4>(
      grid,
      [&](std::span<const Vec3d> wo, std::span<glm::dvec4> out) {
        for (size_t i = 0; i < wo.size(); ++i) out[i] = integrand(wo[i]);
      },
      histogram.probes, options, /*cellsPerBatch=*/100);  // batches that split the grid unevenly
  EXPECT_EQ(batched.values, expected.values);
  EXPECT_EQ(batched.errors, expected.errors);
}

// The dielectric, answering the kit's quadratures in bulk.
class BulkDielectric final : public BsdfModel, public BulkEvaluatedBsdf {
 public:
  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const override {
    return dielectric().eval(wi, wo, mode);
  }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const override {
    return dielectric().pdf(wi, wo, mode);
  }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode mode) const override {
    return dielectric().sample(wi, uLobe, u, mode);
  }
  LobeFlags flags() const override { return dielectric().flags(); }
  double interiorIndex() const override { return dielectric().interiorIndex(); }
  void evalAndPdf(std::span<const Vec3d> wi, std::span<const Vec3d> wo, TransportMode mode, std::span<Rgb> f,
                  std::span<double> pdf) const override {
    ++bulkCalls;
    for (size_t i = 0; i < wo.size(); ++i) {
      f[i] = dielectric().eval(wi[i], wo[i], mode);
      pdf[i] = dielectric().pdf(wi[i], wo[i], mode);
    }
  }
  mutable int bulkCalls = 0;
};

// One angle, a small grid and few samples: the rows are compared, not judged.
BsdfCheckOptions smallKit() {
  BsdfCheckOptions options;
  options.wiThetaDeg = {40};
  options.samples = 20000;
  options.thetaBins = 16;
  options.phiBins = 32;
  return options;
}

void expectSameRows(const CheckReport& rows, const CheckReport& expected) {
  ASSERT_EQ(rows.rows.size(), expected.rows.size());
  for (size_t i = 0; i < rows.rows.size(); ++i) {
    EXPECT_EQ(rows.rows[i].test, expected.rows[i].test);
    EXPECT_EQ(rows.rows[i].statistic, expected.rows[i].statistic) << rows.rows[i].test;
    EXPECT_EQ(rows.rows[i].note, expected.rows[i].note) << rows.rows[i].test;
    EXPECT_EQ(rows.rows[i].passed, expected.rows[i].passed) << rows.rows[i].test;
  }
}

TEST(BatchedQuadrature, AModelAnsweringInBulkGetsTheRowsOfTheSameModelAnsweringOneByOne) {
  const BulkDielectric bulk;
  const CheckReport rows = runBsdfChecks(bulk, "dielectric", smallKit());
  EXPECT_GT(bulk.bulkCalls, 0);  // the kit took the bulk path
  expectSameRows(rows, runBsdfChecks(dielectric(), "dielectric", smallKit()));
}

// The negative controls wrap a bulk model in broken models that answer in bulk too (the swapped
// control asks for pdf(wo, wi) per point): the same rows as the controls of the model itself.
TEST(BatchedQuadrature, NegativeControlsOfAModelAnsweringInBulkGetTheSameRows) {
  const BulkDielectric bulk;
  const CheckReport rows = runNegativeControls(bulk, nullptr, "dielectric", smallKit());
  EXPECT_GT(bulk.bulkCalls, 0);
  expectSameRows(rows, runNegativeControls(dielectric(), nullptr, "dielectric", smallKit()));
}

}  // namespace batched_quadrature_test
}  // namespace scatterlab
