// The environment: equirect orientation as Cycles (peers/make_envmap.py), bilinear radiance,
// rotation, and the importance sampler: consistent with pdf(), normalised, positive wherever
// radiance is, and drawing exactly its pdf by the chi-square kit (which rejects a mismatch).
#include <gtest/gtest.h>

#include "integrator/environment.h"
#include "materials/core/rng.h"
#include "materials/core/warp.h"
#include "render_test_support.h"
#include "validation/chi_square.h"

namespace scatterlab {
namespace environment_test {

using render_test::patchyMap;

TEST(Environment, EquirectOrientationIsCycles) {
  // Image centre faces +X, a quarter from the left +Y, the left edge -X; the top row is +Z.
  EXPECT_NEAR(glm::length(Environment::directionFromEquirect({0.5, 0.5}) - Vec3d(1, 0, 0)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(Environment::directionFromEquirect({0.25, 0.5}) - Vec3d(0, 1, 0)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(Environment::directionFromEquirect({0.75, 0.5}) - Vec3d(0, -1, 0)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(Environment::directionFromEquirect({0.0, 0.5}) - Vec3d(-1, 0, 0)), 0.0, 1e-15);
  EXPECT_NEAR(Environment::directionFromEquirect({0.3, 0.0}).z, 1.0, 1e-15);
  CounterRng rng(5, 0);
  for (int i = 0; i < 1000; ++i) {
    const Vec3d w = sampleUniformSphere(rng.uniform2D());
    const Vec3d back = Environment::directionFromEquirect(Environment::equirectFromDirection(w));
    EXPECT_NEAR(glm::length(back - w), 0.0, 1e-12);
  }
}

TEST(Environment, RadianceIsBilinearBetweenPixelCentres) {
  const Image map = patchyMap(16);
  const Environment env = Environment::fromMap(map, 2.0);
  for (int y = 0; y < 16; y += 3)
    for (int x = 0; x < 32; x += 5) {
      const Vec3d w = Environment::directionFromEquirect({(x + 0.5) / 32, (y + 0.5) / 16});
      EXPECT_NEAR(glm::length(env.eval(w) - 2.0 * map.rgb(x, y)), 0.0, 1e-9) << x << ", " << y;
    }
  // Halfway between column 31 and column 0 (across the seam), on row 4's centre.
  const Vec3d seam = Environment::directionFromEquirect({0.0, 4.5 / 16});
  EXPECT_NEAR(glm::length(env.eval(seam) - (map.rgb(31, 4) + map.rgb(0, 4))), 0.0, 1e-9);
}

TEST(Environment, RotationTurnsTheMap) {
  const Image map = patchyMap(16);
  const Environment plain = Environment::fromMap(map);
  const Transform turn = Transform::rotate(90.0, Vec3d(0, 0, 1));
  const Environment turned = Environment::fromMap(map, 1.0, turn);
  CounterRng rng(6, 0);
  for (int i = 0; i < 200; ++i) {
    const Vec3d w = sampleUniformSphere(rng.uniform2D());
    EXPECT_NEAR(glm::length(turned.eval(turn.vector(w)) - plain.eval(w)), 0.0, 1e-9);
    EXPECT_NEAR(turned.pdf(turn.vector(w)), plain.pdf(w), 1e-9 * plain.pdf(w));
  }
}

TEST(Environment, SamplesAgreeWithEvalAndPdf) {
  const Environment env = Environment::fromMap(patchyMap(16), 1.0, Transform::rotate(30.0, Vec3d(1, 1, 0)));
  CounterRng rng(7, 0);
  for (int i = 0; i < 2000; ++i) {
    const auto s = env.sample(rng.uniform2D());
    ASSERT_TRUE(s);
    EXPECT_NEAR(glm::length(s->direction), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(s->radiance - env.eval(s->direction)), 0.0,
                1e-9 * (1 + glm::length(s->radiance)));
    EXPECT_NEAR(s->pdf, env.pdf(s->direction), 1e-9 * s->pdf);
  }
}

// The density integrates to 1 over the sphere: the midpoint sum over a grid 8 times finer than
// the map's pixels (pdf is constant on each pixel's cell, so the sum is exact up to round-off;
// the densities are stored as floats beside the texels, relative rounding <= 2^-24 each).
TEST(Environment, PdfIntegratesToOne) {
  const Environment env = Environment::fromMap(patchyMap(16));
  const int rows = 128, columns = 256;
  double sum = 0.0;
  for (int r = 0; r < rows; ++r) {
    const double band = (2.0 * Pi / columns) * (std::cos(Pi * r / rows) - std::cos(Pi * (r + 1) / rows));
    for (int c = 0; c < columns; ++c) {
      const double t = (r + 0.5) / rows, u = (c + 0.5) / columns;
      sum += env.pdf(Environment::directionFromEquirect({u, t})) * band;
    }
  }
  EXPECT_NEAR(sum, 1.0, 1e-7);
}

TEST(Environment, PdfIsPositiveWhereverRadianceIs) {
  const Environment env = Environment::fromMap(patchyMap(16));
  CounterRng rng(8, 0);
  int black = 0;
  for (int i = 0; i < 100000; ++i) {
    const Vec3d w = sampleUniformSphere(rng.uniform2D());
    const Rgb l = env.eval(w);
    if (l == Rgb(0.0)) ++black;
    if (l != Rgb(0.0)) {
      EXPECT_GT(env.pdf(w), 0.0) << "radiance " << l.x << " at a zero-density direction";
    }
  }
  EXPECT_GT(black, 0);  // the map has a black band: the check saw both kinds
}

TEST(Environment, ConstantIsUniform) {
  const Environment env = Environment::constant(Rgb(0.5, 1.0, 2.0));
  const auto s = env.sample({0.3, 0.7});
  ASSERT_TRUE(s);
  EXPECT_EQ(s->radiance, Rgb(0.5, 1.0, 2.0));
  EXPECT_DOUBLE_EQ(s->pdf, 1.0 / (4.0 * Pi));
  EXPECT_EQ(env.eval(Vec3d(0, 0, -1)), Rgb(0.5, 1.0, 2.0));
  EXPECT_FALSE(Environment::constant(Rgb(0.0)).sample({0.3, 0.7}));
}

TEST(Environment, RejectsMapsItCannotSample) {
  EXPECT_THROW(Environment::fromMap(Image(30, 16)), std::invalid_argument);
  Image negative = patchyMap(8);
  negative.pixel(3, 2)[1] = -0.5f;
  EXPECT_THROW(Environment::fromMap(negative), std::invalid_argument);
  Image nan = patchyMap(8);
  nan.pixel(3, 2)[0] = NAN;
  EXPECT_THROW(Environment::fromMap(nan), std::invalid_argument);
}

// ---- The sampler through the chi-square kit ---------------------------------------------

// 2 tests at family-wise 1%.
const double Threshold = sidakSignificance(0.01, 2);

ChiSquareOptions kitOptions() {
  ChiSquareOptions o;
  o.grid = {48, 96};
  o.sampleCount = 1'000'000;
  o.seed = 11;
  o.threshold = Threshold;
  // The pdf is piecewise constant with edges that the grid's cells do not follow: adaptive
  // Simpson converges slowly across a jump, so it gets an absolute floor well below what
  // 1e6 samples can resolve (one expected sample is 1e-6 of the mass).
  o.quadrature.relativeTolerance = 1e-6;
  o.quadrature.absoluteTolerance = 1e-10;
  o.quadrature.maxDepth = 16;
  return o;
}

auto drawFrom(const Environment& env) {
  return [&env](CounterRng& rng) -> std::optional<DirectionSample> {
    const auto s = env.sample(rng.uniform2D());
    if (!s) return std::nullopt;
    return DirectionSample{s->direction, s->pdf};
  };
}

TEST(EnvironmentChiSquare, SamplerDrawsItsPdf) {
  const Environment env = Environment::fromMap(patchyMap(16), 1.0, Transform::rotate(40.0, Vec3d(1, 0, 1)));
  const auto r = sphericalChiSquareTest(
      drawFrom(env), [&](const Vec3d& w) { return env.pdf(w); }, kitOptions());
  EXPECT_TRUE(r.passed) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.pValue << " "
                        << r.failure;
}

// Negative control: samples of the turned map against the density of the unturned one.
TEST(EnvironmentChiSquare, RejectsAMismatchedPdf) {
  const Environment turned =
      Environment::fromMap(patchyMap(16), 1.0, Transform::rotate(40.0, Vec3d(1, 0, 1)));
  const Environment plain = Environment::fromMap(patchyMap(16));
  const auto r = sphericalChiSquareTest(
      drawFrom(turned), [&](const Vec3d& w) { return plain.pdf(w); }, kitOptions());
  EXPECT_FALSE(r.passed) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.pValue;
}

}  // namespace environment_test
}  // namespace scatterlab
