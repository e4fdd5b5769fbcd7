// Measured-style tables: the ground truth at cell centres, determinism, and each
// perturbation's statistics against what it promises.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "materials/bsdf/lambertian.h"
#include "materials/core/rng.h"
#include "materials/measured/half_diff.h"
#include "materials/measured/measurement_synthesis.h"
#include "measured_test_support.h"

namespace scatterlab {
namespace measurement_synthesis_test {

using nlohmann::json;

// theta_h cells [0, Rows) of a table: 162,000 cells, 486,000 values per channel triple, enough
// for the statistics below and a tenth of the cost of a whole table.
constexpr int Rows = 10;

MerlTable partialTable(const MeasurementSynthesizer& synthesizer) {
  MerlTable table;
  synthesizer.fillThetaHalfCells(0, Rows, table);
  return table;
}

struct Moments {
  double mean = 0, standardDeviation = 0;
  size_t n = 0;
};
template <typename F> Moments momentsOver(const MerlTable& noisy, const MerlTable& clean, F statistic) {
  double sum = 0, sum2 = 0;
  size_t n = 0;
  for (size_t cell = 0; cell < merl::cellIndex(Rows, 0, 0); ++cell)
    for (int c = 0; c < 3; ++c) {
      if (!(clean.value(c, cell) > 0)) continue;  // unreachable cells hold 0
      const double x = statistic(noisy.value(c, cell), clean.value(c, cell));
      sum += x;
      sum2 += x * x;
      ++n;
    }
  const double mean = sum / double(n);
  return {mean, std::sqrt((sum2 / double(n) - mean * mean) * double(n) / double(n - 1)), n};
}

TEST(MeasurementSynthesis, StoresTheModelAtCellCentres) {
  const LambertianBsdf diffuse(Rgb(0.2, 0.3, 0.4));
  const auto glossy = makeBsdf(json{{"type", "ngan-cook-torrance"}, {"roughness", 0.1}});
  const MeasurementSynthesizer synthesizer({&diffuse, glossy.get()}, {});
  const MerlTable table = partialTable(synthesizer);
  for (size_t cell : {merl::cellIndex(0, 0, 0), merl::cellIndex(3, 40, 17), merl::cellIndex(9, 80, 179)}) {
    const merl::CellCoordinates c = merl::cellCoordinates(cell);
    const auto [wi, wo] =
        directionsFromHalfDiff(merl::thetaHalfAt(c.thetaHalf + 0.5), 0.0,
                               merl::thetaDiffAt(c.thetaDiff + 0.5), merl::phiDiffAt(c.phiDiff + 0.5));
    const Rgb expected = wi.z > 0 && wo.z > 0 ? diffuse.eval(wi, wo) + glossy->eval(wi, wo) : Rgb(0.0);
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_NEAR(table.value(ch, cell), expected[ch], 1e-15 * expected[ch]) << cell;
  }
}

TEST(MeasurementSynthesis, SameSeedSameTableForAnySplitOfTheCells) {
  const LambertianBsdf diffuse(Rgb(0.5));
  MeasurementPerturbation p;
  p.logSigma = 0.2;
  p.noiseFloor = 0.01;
  p.gainSigma = 0.05;
  p.missingAboveDeg = 75;
  p.seed = 99;
  const MeasurementSynthesizer synthesizer({&diffuse}, p);
  const MerlTable whole = synthesizer.synthesize();
  MerlTable pieces;
  for (const auto& [begin, end] :
       {std::pair{60, 90}, {0, 1}, {31, 60}, {1, 2}, {2, 31}})  // out of order, uneven
    synthesizer.fillThetaHalfCells(begin, end, pieces);
  EXPECT_TRUE(whole == pieces);
  EXPECT_TRUE(whole == MeasurementSynthesizer({&diffuse}, p).synthesize());
  p.seed = 100;
  EXPECT_FALSE(partialTable(MeasurementSynthesizer({&diffuse}, p)) == partialTable(synthesizer));
}

// ln(noisy / clean) = sigma z - sigma^2 / 2: its sample mean and standard deviation must match
// within 5 standard errors (sigma / sqrt(n) and sigma / sqrt(2 (n - 1))).
TEST(MeasurementSynthesis, LogNormalNoiseHasTheRequestedSigma) {
  const LambertianBsdf diffuse(Rgb(0.5));
  const MerlTable clean = partialTable(MeasurementSynthesizer({&diffuse}, {}));
  for (double sigma : {0.05, 0.3}) {
    MeasurementPerturbation p;
    p.logSigma = sigma;
    const Moments m = momentsOver(partialTable(MeasurementSynthesizer({&diffuse}, p)), clean,
                                  [](double noisy, double f) { return std::log(noisy / f); });
    EXPECT_NEAR(m.standardDeviation, sigma, 5 * sigma / std::sqrt(2.0 * double(m.n - 1))) << sigma;
    EXPECT_NEAR(m.mean, -0.5 * sigma * sigma, 5 * sigma / std::sqrt(double(m.n))) << sigma;
  }
}

TEST(MeasurementSynthesis, LogNormalNoiseKeepsTheMean) {
  const LambertianBsdf diffuse(Rgb(0.5));
  const MerlTable clean = partialTable(MeasurementSynthesizer({&diffuse}, {}));
  MeasurementPerturbation p;
  p.logSigma = 0.3;
  const Moments m = momentsOver(partialTable(MeasurementSynthesizer({&diffuse}, p)), clean,
                                [](double noisy, double f) { return noisy / f; });
  const double ratioSd = std::sqrt(std::exp(0.09) - 1.0);  // of a mean-1 log-normal
  EXPECT_NEAR(m.mean, 1.0, 5 * ratioSd / std::sqrt(double(m.n)));
}

// Additive noise of standard deviation sqrt(F^2 + F f): with f = 0.8/pi and F = 0.01 the noise
// is 5 sigma below f, so the clamp at 0 touches ~3e-7 of the values.
TEST(MeasurementSynthesis, NoiseFloorHasTheRequestedSpread) {
  const LambertianBsdf diffuse(Rgb(0.8));
  const MerlTable clean = partialTable(MeasurementSynthesizer({&diffuse}, {}));
  MeasurementPerturbation p;
  p.noiseFloor = 0.01;
  const Moments m = momentsOver(partialTable(MeasurementSynthesizer({&diffuse}, p)), clean,
                                [](double noisy, double f) { return noisy - f; });
  const double expected = std::sqrt(0.01 * 0.01 + 0.01 * 0.8 * InvPi);
  EXPECT_NEAR(m.standardDeviation, expected, 5 * expected / std::sqrt(2.0 * double(m.n - 1)));
  EXPECT_NEAR(m.mean, 0.0, 5 * expected / std::sqrt(double(m.n)));
}

TEST(MeasurementSynthesis, NoiseNeverMakesAValueNegative) {
  const LambertianBsdf dark(Rgb(0.01));
  MeasurementPerturbation p;
  p.noiseFloor = 0.05;  // far above the signal
  const MerlTable table = partialTable(MeasurementSynthesizer({&dark}, p));
  EXPECT_EQ(table.missingCount(), 0u);
}

TEST(MeasurementSynthesis, GainErrorScalesEachChannelByItsDrawnGain) {
  const LambertianBsdf diffuse(Rgb(0.5));
  const MerlTable clean = partialTable(MeasurementSynthesizer({&diffuse}, {}));
  MeasurementPerturbation p;
  p.gainSigma = 0.1;
  p.seed = 5;
  const MeasurementSynthesizer synthesizer({&diffuse}, p);
  const MerlTable gained = partialTable(synthesizer);
  const Rgb gains = synthesizer.channelGains();
  for (int c = 0; c < 3; ++c) {
    EXPECT_NE(gains[c], 1.0);
    EXPECT_GT(gains[c], std::exp(-0.5)) << "a 5-sigma gain for sigma 0.1";
    EXPECT_LT(gains[c], std::exp(0.5));
    const size_t cell = merl::cellIndex(4, 20, 30);
    EXPECT_NEAR(gained.value(c, cell) / clean.value(c, cell), gains[c], 1e-14);
  }
  EXPECT_NE(gains.x, gains.y);
}

// Exactly the cells whose centre has wi or wo beyond the cut-off are -1 in every channel.
TEST(MeasurementSynthesis, MissingGrazingCellsAreMarkedNegative) {
  const LambertianBsdf diffuse(Rgb(0.5));
  MeasurementPerturbation p;
  p.missingAboveDeg = 70;
  const MerlTable table = MeasurementSynthesizer({&diffuse}, p).synthesize();
  const double cosCut = std::cos(radians(70.0));
  size_t expected = 0;
  for (size_t cell = 0; cell < merl::CellCount; ++cell) {
    const merl::CellCoordinates c = merl::cellCoordinates(cell);
    const auto [wi, wo] =
        directionsFromHalfDiff(merl::thetaHalfAt(c.thetaHalf + 0.5), 0.0,
                               merl::thetaDiffAt(c.thetaDiff + 0.5), merl::phiDiffAt(c.phiDiff + 0.5));
    const bool grazing = wi.z < cosCut || wo.z < cosCut;
    expected += grazing ? 1 : 0;
    ASSERT_EQ(table.isMissing(cell), grazing) << cell;
    if (grazing) {
      for (int ch = 0; ch < 3; ++ch) ASSERT_EQ(table.stored(ch, cell), -1.0);
    }
  }
  EXPECT_EQ(table.missingCount(), expected);
  EXPECT_GT(expected, merl::CellCount / 4);
}

TEST(MeasurementSynthesis, RejectsInvalidPerturbations) {
  const LambertianBsdf diffuse(Rgb(0.5));
  MeasurementPerturbation p;
  p.logSigma = -0.1;
  EXPECT_THROW(MeasurementSynthesizer({&diffuse}, p), std::invalid_argument);
  p = {};
  p.noiseFloor = std::nan("");
  EXPECT_THROW(MeasurementSynthesizer({&diffuse}, p), std::invalid_argument);
  p = {};
  p.missingAboveDeg = 0;
  EXPECT_THROW(MeasurementSynthesizer({&diffuse}, p), std::invalid_argument);
}

TEST(StandardNormal, BoxMullerHasUnitVarianceAndTheRightTail) {
  CounterRng rng(1, 0);
  constexpr int N = 200000;
  double sum = 0, sum2 = 0;
  int beyond2 = 0;
  for (int i = 0; i < N; ++i) {
    const double u0 = rng.uniform();
    const double z = standardNormal(u0, rng.uniform());
    sum += z;
    sum2 += z * z;
    beyond2 += std::abs(z) > 2 ? 1 : 0;
  }
  EXPECT_NEAR(sum / N, 0.0, 5 / std::sqrt(double(N)));
  EXPECT_NEAR(sum2 / N, 1.0, 5 * std::sqrt(2.0 / N));
  const double tail = std::erfc(2 / std::sqrt(2.0));  // P(|z| > 2) = 0.0455
  EXPECT_NEAR(double(beyond2) / N, tail, 5 * std::sqrt(tail * (1 - tail) / N));
}

}  // namespace measurement_synthesis_test
}  // namespace scatterlab
