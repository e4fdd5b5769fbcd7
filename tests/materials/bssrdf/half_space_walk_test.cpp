// The random walk against the exact half-space solution (docs/validation.md section 6): index
// matched, isotropic, total reflectance within 3 standard errors of 1 - H(mu0) sqrt(1 - c).
// 2e5 paths give standard errors of ~1e-3: a bias of 5e-3 would fail every run.
#include <gtest/gtest.h>

#include "materials/bssrdf/chandrasekhar_h.h"
#include "validation/half_space_reference.h"

namespace scatterlab {
namespace half_space_walk_test {

HalfSpaceWalkSettings settings(double albedo, uint64_t paths, uint64_t seed) {
  HalfSpaceWalkSettings s;
  s.albedo = albedo;
  s.paths = paths;
  s.seed = seed;
  return s;
}

void expectWithinThreeSigma(const HalfSpaceWalkResult& walk, double exact) {
  EXPECT_LE(std::abs(walk.totalReflectance - exact), 3.0 * walk.totalStdError)
      << "walk " << walk.totalReflectance << " +- " << walk.totalStdError << ", exact " << exact;
}

TEST(HalfSpaceWalk, NormalIncidenceMatchesTheHFunction) {
  for (const double c : {0.3, 0.8, 0.99}) {
    SCOPED_TRACE(c);
    const HalfSpaceWalkResult walk = simulateHalfSpace(settings(c, 200000, 11));
    EXPECT_EQ(walk.truncated, 0u);
    expectWithinThreeSigma(walk, ChandrasekharH(c).directionalAlbedo(1.0));
  }
}

TEST(HalfSpaceWalk, ObliqueIncidenceMatchesTheHFunction) {
  HalfSpaceWalkSettings s = settings(0.8, 100000, 12);
  s.incidentCosTheta = 0.4;
  expectWithinThreeSigma(simulateHalfSpace(s), ChandrasekharH(0.8).directionalAlbedo(0.4));
}

TEST(HalfSpaceWalk, DiffuseIncidenceMatchesTheWhiteSkyAlbedo) {
  HalfSpaceWalkSettings s = settings(0.8, 100000, 13);
  s.incidence = WalkIncidence::Diffuse;
  expectWithinThreeSigma(simulateHalfSpace(s), ChandrasekharH(0.8).whiteSkyAlbedo());
}

TEST(HalfSpaceWalk, SameResultForAnyThreadCount) {
  HalfSpaceWalkSettings s = settings(0.9, 20000, 14);
  s.eta = 1.4;
  s.g = 0.5;
  s.radiusEdges = logRadiusEdges(0.01, 20.0, 12);
  s.threads = 1;
  const HalfSpaceWalkResult one = simulateHalfSpace(s);
  s.threads = 2;
  const HalfSpaceWalkResult two = simulateHalfSpace(s);
  EXPECT_EQ(one.escaped, two.escaped);
  EXPECT_EQ(one.scatteringEvents, two.scatteringEvents);
  EXPECT_EQ(one.counts, two.counts);
  EXPECT_EQ(one.singleCounts, two.singleCounts);
  EXPECT_EQ(one.singleEscaped, two.singleEscaped);
}

TEST(HalfSpaceWalk, NothingIsLostWithoutAbsorptionBehindAFresnelBoundary) {
  // c = 1: every path leaves eventually (internal reflections included) or hits the cap.
  HalfSpaceWalkSettings s = settings(1.0, 2000, 15);
  s.eta = 1.3;
  s.maxScatteringEvents = 20000;
  const HalfSpaceWalkResult walk = simulateHalfSpace(s);
  EXPECT_EQ(walk.absorbed, 0u);
  EXPECT_EQ(walk.escaped + walk.truncated, s.paths);
  EXPECT_LT(walk.truncated, s.paths / 50);  // P(T > n) ~ n^(-1/2) for the half-space return time
}

TEST(HalfSpaceWalk, AFresnelBoundaryKeepsLightInside) {
  // The same medium reflects less behind an index mismatch: internal reflection gives the walk
  // more chances to be absorbed.
  HalfSpaceWalkSettings matched = settings(0.9, 50000, 16), glass = matched;
  glass.eta = 1.5;
  const HalfSpaceWalkResult a = simulateHalfSpace(matched), b = simulateHalfSpace(glass);
  EXPECT_GT(a.totalReflectance - b.totalReflectance, 5 * std::hypot(a.totalStdError, b.totalStdError));
}

TEST(HalfSpaceWalk, ProfileAnnuliAddUpToTheEscapedFraction) {
  HalfSpaceWalkSettings s = settings(0.95, 20000, 17);
  s.extinction = 2.0;
  s.radiusEdges = logRadiusEdges(1e-3, 1e4, 30);  // out to where nothing escapes
  const HalfSpaceWalkResult walk = simulateHalfSpace(s);
  uint64_t inAnnuli = 0;
  double integral = 0.0;
  for (size_t k = 0; k < walk.counts.size(); ++k) {
    inAnnuli += walk.counts[k];
    integral += walk.profile[k] * Pi * (sqr(s.radiusEdges[k + 1]) - sqr(s.radiusEdges[k]));
    EXPECT_GE(walk.profileStdError[k], 0.0);
  }
  EXPECT_EQ(inAnnuli, walk.escaped);
  EXPECT_NEAR(integral, walk.totalReflectance, 1e-12);
}

// Single scattering of a normally incident beam, index-matched and isotropic, in closed form:
// the first collision at optical depth z (density e^-z), scattered with probability c into a
// uniformly distributed direction, leaves upward along mu with probability e^(-z / mu):
// R1 = c int_0^inf e^-z dz int_0^1 (1/2) e^(-z/mu) dmu = (c / 2) int_0^1 mu / (1 + mu) dmu
//    = (c / 2)(1 - ln 2).
TEST(HalfSpaceWalk, SingleScatteringMatchesItsClosedForm) {
  for (const double c : {0.3, 0.9}) {
    SCOPED_TRACE(c);
    HalfSpaceWalkSettings s = settings(c, 200000, 18);
    s.radiusEdges = logRadiusEdges(1e-2, 30.0, 8);
    const HalfSpaceWalkResult walk = simulateHalfSpace(s);
    const double exact = 0.5 * c * (1.0 - std::log(2.0));
    EXPECT_LE(std::abs(walk.singleReflectance - exact), 3.0 * walk.singleStdError)
        << "walk " << walk.singleReflectance << " +- " << walk.singleStdError << ", exact " << exact;
    // The annuli split the single-scattering paths too, and the rest is multiple scattering.
    uint64_t single = 0;
    const std::vector<double> multiple = walk.multipleScatteringProfile();
    for (size_t k = 0; k < walk.counts.size(); ++k) {
      single += walk.singleCounts[k];
      EXPECT_LE(walk.singleCounts[k], walk.counts[k]);
      const double area = Pi * (sqr(s.radiusEdges[k + 1]) - sqr(s.radiusEdges[k]));
      EXPECT_NEAR(multiple[k] * area * double(s.paths), double(walk.counts[k] - walk.singleCounts[k]), 1e-6);
    }
    EXPECT_LE(single, walk.singleEscaped);
  }
}

// A denormal extinction passes validation (positive, finite), but every free path is then
// infinite and the position stops being finite: each path is counted as such, and none of them
// is passed off as absorbed or escaped. With sigma_t = 1 none is.
TEST(HalfSpaceWalk, PathsThatStopBeingFiniteAreCountedApart) {
  HalfSpaceWalkSettings s = settings(0.8, 200, 9);
  s.extinction = 1e-320;
  s.radiusEdges = linearRadiusEdges(1.0, 4);
  const HalfSpaceWalkResult walk = simulateHalfSpace(s);
  EXPECT_EQ(walk.nonFinite, s.paths);
  EXPECT_EQ(walk.escaped + walk.absorbed + walk.truncated, 0u);
  EXPECT_EQ(walk.totalReflectance, 0.0);
  s.extinction = 1.0;
  const HalfSpaceWalkResult sound = simulateHalfSpace(s);
  EXPECT_EQ(sound.nonFinite, 0u);
  EXPECT_EQ(sound.escaped + sound.absorbed + sound.truncated, s.paths);
}

TEST(HalfSpaceWalk, RejectsSettingsOutOfRange) {
  HalfSpaceWalkSettings s;
  s.albedo = 1.2;
  EXPECT_THROW(simulateHalfSpace(s), std::invalid_argument);
  s = HalfSpaceWalkSettings{};
  s.eta = 0.0;
  EXPECT_THROW(simulateHalfSpace(s), std::invalid_argument);
  s = HalfSpaceWalkSettings{};
  s.radiusEdges = {0.1, 1.0};
  EXPECT_THROW(simulateHalfSpace(s), std::invalid_argument);
}

}  // namespace half_space_walk_test
}  // namespace scatterlab
