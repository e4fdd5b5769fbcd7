// chooseLobe (materials/core/lobe_choice.h): lobes drawn with their probabilities, the remapped
// number uniform in [0, 1) within every lobe and never 1, zero-probability lobes never drawn,
// the rule for probabilities that miss 1 by rounding, and the exact comparisons and remap the
// models used before they shared the helper.
#include "materials/core/lobe_choice.h"

#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "materials/core/rng.h"

namespace scatterlab {
namespace lobe_choice_test {

// Zero lobes first, between and last, and lobes from 5% to 45%.
constexpr std::array<double, 7> Probabilities{0.0, 0.05, 0.3, 0.0, 0.2, 0.45, 0.0};
constexpr size_t Draws = 1'000'000;
constexpr int Bins = 10;
// A count of n Bernoulli(p) trials has standard error sqrt(n p (1 - p)); 5 of them is exceeded
// with probability 6e-7 per check, so the ~50 checks below fail by chance with < 1e-4.
constexpr double Sigmas = 5.0;

double binomialTolerance(double n, double p) { return Sigmas * std::sqrt(n * p * (1.0 - p)); }

struct Histogram {
  std::array<double, Probabilities.size()> lobes{};
  std::array<std::array<double, Bins>, Probabilities.size()> remapped{};
};

Histogram drawLobes() {
  Histogram h;
  CounterRng rng(7, 0);
  for (size_t k = 0; k < Draws; ++k) {
    const LobeChoice c = chooseLobe(rng.uniform(), Probabilities);
    EXPECT_GE(c.lobe, 0);
    if (c.lobe < 0) continue;
    EXPECT_GE(c.u, 0.0);
    EXPECT_LT(c.u, 1.0);
    h.lobes[size_t(c.lobe)] += 1;
    h.remapped[size_t(c.lobe)][size_t(std::min(int(c.u * Bins), Bins - 1))] += 1;
  }
  return h;
}

TEST(LobeChoice, FrequenciesMatchTheProbabilities) {
  const Histogram h = drawLobes();
  for (size_t i = 0; i < Probabilities.size(); ++i)
    EXPECT_NEAR(h.lobes[i], Draws * Probabilities[i], binomialTolerance(Draws, Probabilities[i]))
        << "lobe " << i;
}

TEST(LobeChoice, ZeroProbabilityLobesAreNeverChosen) {
  const Histogram h = drawLobes();
  for (size_t i = 0; i < Probabilities.size(); ++i)
    if (Probabilities[i] == 0.0) {
      EXPECT_EQ(h.lobes[i], 0.0) << "lobe " << i;
    }
  // Nor at the ends of [0, 1), where a zero lobe borders the first and the last positive one.
  EXPECT_EQ(chooseLobe(0.0, Probabilities).lobe, 1);
  EXPECT_EQ(chooseLobe(std::nextafter(1.0, 0.0), Probabilities).lobe, 5);
  // Nor at the boundary between two positive lobes with a zero lobe between them.
  EXPECT_EQ(chooseLobe(Probabilities[1] + Probabilities[2], Probabilities).lobe, 4);
}

TEST(LobeChoice, RemappedNumberIsUniformWithinEveryLobe) {
  const Histogram h = drawLobes();
  for (size_t i = 0; i < Probabilities.size(); ++i) {
    if (Probabilities[i] == 0.0) continue;
    for (int b = 0; b < Bins; ++b)
      EXPECT_NEAR(h.remapped[i][size_t(b)], h.lobes[i] / Bins, binomialTolerance(h.lobes[i], 1.0 / Bins))
          << "lobe " << i << " bin " << b;
  }
}

TEST(LobeChoice, RemappedNumberNeverReachesOne) {
  const double largest = std::nextafter(1.0, 0.0);
  EXPECT_LT(chooseLobe(largest, Probabilities).u, 1.0);
  EXPECT_LT(chooseLobe(largest, 0.3).u, 1.0);
  // Just below every lobe's upper end.
  double cdf = 0.0;
  for (size_t i = 0; i < Probabilities.size(); ++i) {
    cdf += Probabilities[i];
    if (Probabilities[i] == 0.0 || cdf >= 1.0) continue;
    const LobeChoice c = chooseLobe(std::nextafter(cdf, 0.0), Probabilities);
    EXPECT_EQ(c.lobe, int(i));
    EXPECT_LT(c.u, 1.0) << "lobe " << i;
  }
  // Probabilities 1/2 and 1/2 - 2^-53 sum to the largest double below 1, which is then beyond the
  // total: (uLobe - 1/2) / (1/2 - 2^-53) is exactly 1, and the clamp gives OneMinusEpsilon.
  const std::array<double, 2> short2{0.5, 0.5 - 0x1.0p-53};
  const LobeChoice c = chooseLobe(largest, short2);
  EXPECT_EQ(c.lobe, 1);
  EXPECT_EQ(c.u, OneMinusEpsilon);
}

// The rule of lobe_choice.h: a uLobe beyond a total short of 1 goes to the last positive lobe
// (trailing zero lobes are skipped); a total above 1 shortens the last lobe's interval.
TEST(LobeChoice, RoundingShortfallGoesToTheLastPositiveLobe) {
  const std::array<double, 4> shortOfOne{0.25, 0.75 - 1e-15, 0.0, 0.0};
  EXPECT_EQ(chooseLobe(1.0 - 1e-16, shortOfOne).lobe, 1);
  const std::array<double, 2> aboveOne{0.25, 0.75 + 1e-15};
  const LobeChoice c = chooseLobe(std::nextafter(1.0, 0.0), aboveOne);
  EXPECT_EQ(c.lobe, 1);
  EXPECT_LT(c.u, 1.0);
  EXPECT_EQ(chooseLobe(0.24, aboveOne).lobe, 0);
}

TEST(LobeChoice, NoPositiveProbabilityChoosesNoLobe) {
  const std::array<double, 3> zeros{0.0, 0.0, 0.0};
  EXPECT_EQ(chooseLobe(0.5, zeros).lobe, -1);
  EXPECT_EQ(chooseLobe(0.5, std::span<const double>()).lobe, -1);
  EXPECT_EQ(chooseLobe(0.5, std::nan("")).lobe, -1);
}

// The two-lobe form chooses lobe 0 exactly when uLobe < p and remaps as the models did by hand
// (uLobe / p, or (uLobe - p) / (1 - p)), to the bit, so that their samples did not change.
TEST(LobeChoice, TwoLobesMatchTheHandWrittenComparisonBitForBit) {
  CounterRng rng(11, 0);
  const std::vector<double> ps{0.0, 1e-300, 0.1, 1.0 / 3.0, 0.5, 0.9, std::nextafter(1.0, 0.0), 1.0, 1.5};
  for (const double p : ps) {
    std::vector<double> us{0.0, std::nextafter(1.0, 0.0)};
    if (p > 0 && p < 1) us.insert(us.end(), {p, std::nextafter(p, 0.0)});
    for (int k = 0; k < 1000; ++k) us.push_back(rng.uniform());
    for (const double u : us) {
      const LobeChoice c = chooseLobe(u, p);
      EXPECT_EQ(c.lobe, u < p ? 0 : 1) << "p " << p << " u " << u;
      const double handWritten = u < p ? u / p : (u - p) / (1.0 - p);
      if (handWritten < 1.0) {
        EXPECT_EQ(c.u, handWritten) << "p " << p << " u " << u;
      }
    }
  }
}

// Three lobes as the Disney BRDF chose them: diffuse below p_d, clearcoat at or above p_d + p_s.
TEST(LobeChoice, ThreeLobesMatchTheCumulativeComparisons) {
  CounterRng rng(13, 0);
  const std::array<double, 3> p{0.2, 0.7, 0.1};
  for (int k = 0; k < 10'000; ++k) {
    const double u = rng.uniform();
    const int expected = u < p[0] ? 0 : (u >= p[0] + p[1] ? 2 : 1);
    EXPECT_EQ(chooseLobe(u, p).lobe, expected) << "u " << u;
  }
}

}  // namespace lobe_choice_test
}  // namespace scatterlab
