// The tabulated BRDF's evaluation: it reproduces the table at cell centres, interpolates a
// table made from an analytic model back to the model within the error that the binning
// allows, is reciprocal and isotropic, and fills missing and unreachable cells by its rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "materials/core/rng.h"
#include "materials/core/warp.h"
#include "materials/measured/tabulated_brdf.h"
#include "measured_test_support.h"

namespace scatterlab {
namespace tabulated_brdf_test {

using measured_test::synthesise;
using nlohmann::json;

// Float storage of the table: 2^-24 relative, with room for the interpolation's sums.
constexpr double FloatRounding = 1e-6;

Vec3d rotateAboutZ(const Vec3d& w, double angle) {
  return {w.x * std::cos(angle) - w.y * std::sin(angle), w.x * std::sin(angle) + w.y * std::cos(angle), w.z};
}

Vec3d randomDirection(CounterRng& rng, double maxThetaDeg) {
  return sampleUniformCone(rng.uniform2D(), std::cos(radians(maxThetaDeg)));
}

// ---- Cell centres ----------------------------------------------------------------------------

TEST(TabulatedBrdf, ReproducesTheTableAtCellCentres) {
  const auto truth = synthesise({json{{"type", "conductor"}, {"alpha", 0.2}, {"metal", "Cu"}},
                                 json{{"type", "lambertian"}, {"albedo", 0.3}}});
  const TabulatedBrdf brdf(truth.table);
  CounterRng rng(5, 0);
  int checked = 0;
  while (checked < 2000) {
    const size_t cell = size_t(rng.uniform() * double(merl::CellCount));
    if (!isReachableCell(cell)) continue;
    const merl::CellCoordinates c = merl::cellCoordinates(cell);
    // Any phi_h: the table is isotropic.
    const auto [wi, wo] =
        directionsFromHalfDiff(merl::thetaHalfAt(c.thetaHalf + 0.5), 2.0 * Pi * rng.uniform(),
                               merl::thetaDiffAt(c.thetaDiff + 0.5), merl::phiDiffAt(c.phiDiff + 0.5));
    const Rgb f = brdf.eval(wi, wo);
    for (int ch = 0; ch < 3; ++ch)
      ASSERT_NEAR(f[ch], truth.table.value(ch, cell), FloatRounding * truth.table.value(ch, cell))
          << "cell " << cell;
    ++checked;
  }
}

// ---- Interpolation against the generating model ----------------------------------------------
//
// The bound. Trilinear interpolation is I = Ix Iy Iz, one linear interpolation per axis in
// the cells' index coordinates x_k (spacing 1), so
//   f - I f = (f - Ix f) + Ix (f - Iy f) + Ix Iy (f - Iz f),
// and since each I_k is a convex combination, |f - I f| <= sum_k max |f - I_k f| <=
// (1/8) sum_k max_cell |d^2 f / d x_k^2| (the 1-D linear-interpolation error h^2/8 max|f''|,
// h = 1). The second derivatives are estimated by the central second differences of the
// generating model at the cell's 8 corners, f(c - e_k) - 2 f(c) + f(c + e_k): each equals
// f''(xi) somewhere within one cell of the corner. The bound checked is
//   |f_table - f_model| <= (1/8) sum_k max_corners |second difference_k| (1 + Slack) + float
// with Slack for the curvature between the sampled second differences (measured over 3000
// points each: the worst point reaches 0.97-0.98 of the bound without slack; see the printed
// ratio).
constexpr double Slack = 0.5;

struct InterpolationStats {
  int points = 0;
  double worstRatio = 0;   // max error / (bound + float rounding)
  double sumRelative = 0;  // for the mean relative error
  double maxRelative = 0;
};

// f of `truth` at continuous index coordinates (cell centres are at i + 0.5).
Rgb modelAt(const measured_test::SynthesisedTable& truth, double xh, double xd, double xp) {
  const auto [wi, wo] =
      directionsFromHalfDiff(merl::thetaHalfAt(xh), 0.0, merl::thetaDiffAt(xd), merl::phiDiffAt(xp));
  return truth.truth(wi, wo);
}

InterpolationStats checkInterpolation(const measured_test::SynthesisedTable& truth, int points,
                                      uint64_t seed) {
  const TabulatedBrdf brdf(truth.table);
  InterpolationStats stats;
  CounterRng rng(seed, 0);
  while (stats.points < points) {
    const Vec3d wi = randomDirection(rng, 75.0), wo = randomDirection(rng, 75.0);
    const HalfDiff hd = halfDiffFromDirections(wi, wo);
    const double xh = merl::thetaHalfCoordinate(hd.thetaHalf) - 0.5;
    const double xd = merl::thetaDiffCoordinate(hd.thetaDiff) - 0.5;
    const double xp = merl::phiDiffCoordinate(merl::foldPhiDiff(hd.phiDiff)) - 0.5;
    // Corners and their neighbours inside the table (no clamping, no filled cells).
    if (xh < 1 || xh >= 88 || xd < 1 || xd >= 88) continue;
    const int h0 = int(xh), d0 = int(xd), p0 = int(std::floor(xp));
    bool reachable = true;
    Rgb secondDifference[3] = {Rgb(0.0), Rgb(0.0), Rgb(0.0)};  // per axis: max |second difference|
    for (int a = -1; a <= 2; ++a)
      for (int b = -1; b <= 2; ++b)
        for (int c = -1; c <= 2; ++c)
          reachable =
              reachable && isReachableCell(merl::cellIndex(
                               h0 + a, d0 + b, (p0 + c + 2 * merl::PhiDiffCells) % merl::PhiDiffCells));
    if (!reachable) continue;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b)
        for (int c = 0; c < 2; ++c) {
          const double ch = h0 + a + 0.5, cd = d0 + b + 0.5, cp = p0 + c + 0.5;
          const Rgb centre = modelAt(truth, ch, cd, cp);
          const Rgb along[3] = {modelAt(truth, ch - 1, cd, cp) + modelAt(truth, ch + 1, cd, cp),
                                modelAt(truth, ch, cd - 1, cp) + modelAt(truth, ch, cd + 1, cp),
                                modelAt(truth, ch, cd, cp - 1) + modelAt(truth, ch, cd, cp + 1)};
          for (int k = 0; k < 3; ++k)
            secondDifference[k] = glm::max(secondDifference[k], glm::abs(along[k] - 2.0 * centre));
        }
    const Rgb bound = (secondDifference[0] + secondDifference[1] + secondDifference[2]) / 8.0;
    const Rgb table = brdf.eval(wi, wo), model = truth.truth(wi, wo);
    for (int ch = 0; ch < 3; ++ch) {
      const double error = std::abs(table[ch] - model[ch]);
      const double allowed = bound[ch] * (1 + Slack) + FloatRounding * model[ch];
      EXPECT_LE(error, allowed) << "channel " << ch << " at theta_h " << degrees(hd.thetaHalf) << " theta_d "
                                << degrees(hd.thetaDiff) << " phi_d " << degrees(hd.phiDiff) << ": table "
                                << table[ch] << " model " << model[ch] << " bound " << bound[ch];
      stats.worstRatio = std::max(stats.worstRatio, error / (bound[ch] + FloatRounding * model[ch]));
      const double relative = error / model[ch];
      stats.sumRelative += relative;
      stats.maxRelative = std::max(stats.maxRelative, relative);
    }
    ++stats.points;
  }
  return stats;
}

void report(const std::string& name, const InterpolationStats& s) {
  std::printf(
      "[ interpolation ] %s: %d points, worst error / bound %.3f, relative error mean %.2e max %.2e\n",
      name.c_str(), s.points, s.worstRatio, s.sumRelative / (3 * s.points), s.maxRelative);
}

TEST(TabulatedBrdfInterpolation, GgxConductorWithinTheBinningBound) {
  for (double alpha : {0.05, 0.3}) {
    SCOPED_TRACE(alpha);
    const auto truth = synthesise({json{{"type", "conductor"}, {"alpha", alpha}, {"metal", "Au"}}});
    const InterpolationStats stats = checkInterpolation(truth, 3000, 17);
    report("ggx alpha " + std::to_string(alpha), stats);
    EXPECT_LT(stats.worstRatio, 1 + Slack);
  }
}

TEST(TabulatedBrdfInterpolation, BlinnPhongPlusDiffuseWithinTheBinningBound) {
  const auto truth =
      synthesise({json{{"type", "blinn-phong"}, {"kd", 0.3}, {"ks", 0.05}, {"exponent", 2000}}});
  const InterpolationStats stats = checkInterpolation(truth, 3000, 19);
  report("blinn-phong n 2000", stats);
  EXPECT_LT(stats.worstRatio, 1 + Slack);
}

// ---- Symmetries -------------------------------------------------------------------------------

TEST(TabulatedBrdf, IsReciprocalAndIsotropic) {
  const auto truth = synthesise(measured_test::publishedFit("alum-bronze"));
  const TabulatedBrdf brdf(truth.table);
  CounterRng rng(23, 0);
  for (int i = 0; i < 5000; ++i) {
    const Vec3d wi = sampleUniformHemisphere(rng.uniform2D()), wo = sampleUniformHemisphere(rng.uniform2D());
    const Rgb f = brdf.eval(wi, wo);
    const Rgb swapped = brdf.eval(wo, wi);
    const double angle = 2.0 * Pi * rng.uniform();
    const Rgb rotated = brdf.eval(rotateAboutZ(wi, angle), rotateAboutZ(wo, angle));
    for (int c = 0; c < 3; ++c) {
      ASSERT_LE(relativeDifference(f[c], swapped[c]), 1e-9) << i;
      ASSERT_LE(relativeDifference(f[c], rotated[c]), 1e-7) << i;  // rotation moves the angles by round-off
    }
  }
}

TEST(TabulatedBrdf, BelowTheSurfaceIsZero) {
  const auto truth = synthesise({json{{"type", "lambertian"}}});
  const TabulatedBrdf brdf(truth.table);
  EXPECT_EQ(brdf.eval(Vec3d(0, 0, 1), Vec3d(0.6, 0, -0.8)), Rgb(0.0));
  EXPECT_EQ(brdf.eval(Vec3d(0.6, 0, -0.8), Vec3d(0, 0, 1)), Rgb(0.0));
  EXPECT_EQ(brdf.pdf(Vec3d(0, 0, 1), Vec3d(0.6, 0, -0.8)), 0.0);
  EXPECT_FALSE(brdf.sample(Vec3d(0.6, 0, -0.8), 0.5, Vec2d(0.5)).has_value());
}

// ---- The fill rule ------------------------------------------------------------------------------

// Cells whose centre no reflection reaches hold 0 in scatterlab's tables; they must not pull
// grazing values down: a Lambertian table stays albedo / pi right up to the horizon.
TEST(TabulatedBrdfFill, UnreachableCellsDoNotDarkenGrazingPairs) {
  const auto truth = synthesise({json{{"type", "lambertian"}, {"albedo", 0.8}}});
  const TabulatedBrdf brdf(truth.table);
  EXPECT_EQ(brdf.missingCells(), 0u);
  EXPECT_GT(brdf.filledCells(), merl::CellCount / 10);  // the unreachable corner of the table
  CounterRng rng(29, 0);
  for (int i = 0; i < 2000; ++i) {
    const Vec3d wi = directionFromDegrees(80 + 9.9 * rng.uniform(), 360 * rng.uniform());
    const Vec3d wo = directionFromDegrees(80 + 9.9 * rng.uniform(), 360 * rng.uniform());
    ASSERT_NEAR(brdf.eval(wi, wo).x, 0.8 * InvPi, FloatRounding) << i;
  }
}

TEST(TabulatedBrdfFill, MissingCellsTakeTheNearestMeasuredThetaDiff) {
  MeasurementPerturbation missing;
  missing.missingAboveDeg = 60;
  const auto truth = synthesise(measured_test::publishedFit("red-plastic"), missing);
  const TabulatedBrdf brdf(truth.table);
  EXPECT_EQ(brdf.missingCells(), truth.table.missingCount());
  EXPECT_GT(brdf.missingCells(), 0u);
  // In every (theta_h, phi_d) column, a missing cell takes the value of the nearest usable
  // cell along theta_d (ties: the smaller theta_d).
  CounterRng rng(31, 0);
  int checked = 0;
  while (checked < 300) {
    const size_t cell = size_t(rng.uniform() * double(merl::CellCount));
    if (!truth.table.isMissing(cell)) continue;
    const merl::CellCoordinates c = merl::cellCoordinates(cell);
    int nearest = -1;
    for (int distance = 1; distance < merl::ThetaDiffCells && nearest < 0; ++distance)
      for (int td : {c.thetaDiff - distance, c.thetaDiff + distance}) {
        if (td < 0 || td >= merl::ThetaDiffCells || nearest >= 0) continue;
        const size_t other = merl::cellIndex(c.thetaHalf, td, c.phiDiff);
        if (!truth.table.isMissing(other) && isReachableCell(other)) nearest = td;
      }
    if (nearest < 0) continue;  // the column has no usable cell: covered below
    const size_t source = merl::cellIndex(c.thetaHalf, nearest, c.phiDiff);
    for (int ch = 0; ch < 3; ++ch)
      ASSERT_FLOAT_EQ(float(brdf.cellValue(cell)[ch]), float(truth.table.value(ch, source))) << cell;
    ++checked;
  }
}

TEST(TabulatedBrdfFill, AnEmptyColumnTakesTheNearestThetaHalf) {
  auto truth = synthesise({json{{"type", "lambertian"}, {"albedo", 0.5}}});
  // theta_h cell 10 varies with phi_d; then the column (theta_h 10, phi_d 7) goes missing.
  for (int td = 0; td < merl::ThetaDiffCells; ++td) {
    truth.table.setRgb(merl::cellIndex(9, td, 7), Rgb(0.25));
    truth.table.setRgb(merl::cellIndex(11, td, 7), Rgb(0.75));
    truth.table.setMissing(merl::cellIndex(10, td, 7));
  }
  const TabulatedBrdf brdf(truth.table);
  EXPECT_EQ(brdf.missingCells(), size_t(merl::ThetaDiffCells));
  EXPECT_FLOAT_EQ(float(brdf.cellValue(merl::cellIndex(10, 5, 7)).y), 0.25f);  // tie: the smaller theta_h
}

TEST(TabulatedBrdfFill, NothingMeasuredGivesZeroNeverNegative) {
  MerlTable table;
  for (size_t cell = 0; cell < merl::CellCount; ++cell) table.setMissing(cell);
  const TabulatedBrdf brdf(table);
  EXPECT_EQ(brdf.missingCells(), merl::CellCount);
  EXPECT_EQ(brdf.eval(directionFromDegrees(30, 0), directionFromDegrees(40, 170)), Rgb(0.0));
  // With nothing to sample from, the sampler falls back to cosine sampling, pdf > 0.
  EXPECT_GT(brdf.pdf(directionFromDegrees(30, 0), directionFromDegrees(40, 170)), 0.0);
}

TEST(TabulatedBrdfFill, NoisyTableWithMissingGrazingNeverEvaluatesNegative) {
  MeasurementPerturbation noisy;
  noisy.logSigma = 0.3;
  noisy.noiseFloor = 0.05;
  noisy.missingAboveDeg = 70;
  const auto truth = synthesise(measured_test::publishedFit("chrome"), noisy);
  const TabulatedBrdf brdf(truth.table);
  CounterRng rng(37, 0);
  for (int i = 0; i < 20000; ++i) {
    const Rgb f =
        brdf.eval(sampleUniformHemisphere(rng.uniform2D()), sampleUniformHemisphere(rng.uniform2D()));
    ASSERT_TRUE(isFinite(f) && f.x >= 0 && f.y >= 0 && f.z >= 0) << i;
  }
}

}  // namespace tabulated_brdf_test
}  // namespace scatterlab
