// Every diffusion profile against the half-space random walk (docs/validation.md section 6): the numbers the
// physics of each model says they should have. `scatterlab profile MATERIAL --reference walk
// --compare` prints the same table for any medium.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "materials/bssrdf/measured_media.h"
#include "validation/profile_comparison.h"

namespace scatterlab {
namespace profile_comparison_test {

ScatteringMedium skin1() {
  const MeasuredMedium* m = findMeasuredMedium("Skin1");
  ScatteringMedium medium;
  medium.sigmaS = m->sigmaSPrime;
  medium.sigmaA = m->sigmaA;
  medium.eta = m->eta;
  return medium;
}

// Index-matched, isotropic, sigma_t = 1, single-scattering albedos 0.7, 0.9, 0.99.
ScatteringMedium indexMatched() {
  ScatteringMedium medium;
  medium.sigmaS = Rgb(0.7, 0.9, 0.99);
  medium.sigmaA = Rgb(1.0) - medium.sigmaS;
  medium.eta = 1.0;
  return medium;
}

ProfileComparison compare(const ScatteringMedium& medium, uint64_t paths) {
  ProfileComparisonOptions options;
  options.paths = paths;
  options.seed = 3;
  const ProfileComparison c = compareProfilesWithWalk(medium, options);
  for (const ModelComparison& m : c.models)
    std::printf(
        "%-15s total error %+6.1f%% %+6.1f%% %+6.1f%%  profile error %5.1f%% %5.1f%% %5.1f%%  "
        "(multiple only: total %+6.1f%% %+6.1f%% %+6.1f%%)\n",
        toString(m.model).c_str(), 100 * m.errors.totalError.x, 100 * m.errors.totalError.y,
        100 * m.errors.totalError.z, 100 * m.errors.profileError.x, 100 * m.errors.profileError.y,
        100 * m.errors.profileError.z, 100 * m.errors.multipleTotalError.x,
        100 * m.errors.multipleTotalError.y, 100 * m.errors.multipleTotalError.z);
  return c;
}

// d'Eon 2012's better dipole has the prefactor alpha'^2 / (4 pi): Grosjean's approximation
// separates a point source's first (uncollided) flight from the collided light and describes
// only the latter, alpha' of the source, by diffusion (d'Eon 2014, arXiv:1312.1412), so the
// dipole at z_r = 1 / sigma_t' (the first collision, strength alpha') carries the light that
// scatters at least twice. Its total is then a fixed multiple of the walk's multiple
// scattering in every channel, although alpha' runs from 0.68 to 0.96 (Skin1) and 0.7 to 0.99
// (index-matched): measured with 1e6 paths, the ratio varies across channels by 2% (Skin1) and
// 3.4% (index-matched); the bound is 4% plus three standard errors of the walk. A prefactor
// alpha' would make it vary with alpha' by over 40%. The common factor is the diffusion
// approximation's own error: +9..+11% behind Skin1's Fresnel boundary, +20..+24% index-matched.
TEST(ProfileComparison, TheBetterDipoleIsTheMultipleScatteringWithPrefactorAlphaPrimeSquared) {
  for (const auto& [medium, upper] : {std::pair{skin1(), 1.15}, std::pair{indexMatched(), 1.3}}) {
    SCOPED_TRACE(medium.eta);
    const ProfileComparison c = compare(medium, 200000);
    const ProfileErrors& e = c.find(ProfileModel::BetterDipole).errors;
    double lowest = 1e9, highest = 0, worstNoise = 0;
    for (int ch = 0; ch < 3; ++ch) {
      const double ratio = e.total[ch] / c.walkMultipleTotal[ch];
      lowest = std::min(lowest, ratio);
      highest = std::max(highest, ratio);
      worstNoise = std::max(worstNoise, c.walkMultipleStdError[ch] / c.walkMultipleTotal[ch]);
      EXPECT_GT(ratio, 1.0) << ch;
      EXPECT_LT(ratio, upper) << ch;
    }
    EXPECT_LT(highest / lowest - 1.0, 0.04 + 3.0 * std::sqrt(2.0) * worstNoise);
    const Rgb alphaPrime = medium.reducedAlbedo();
    EXPECT_GT(std::max({alphaPrime.x, alphaPrime.y, alphaPrime.z}) /
                  std::min({alphaPrime.x, alphaPrime.y, alphaPrime.z}),
              1.4);
  }
}

// Behind a Fresnel boundary (Skin1, eta 1.3) photon beam diffusion, which integrates the
// better dipole along the refracted beam and adds exact single scattering, is the closest of
// the four to the walk of all orders in every channel, within 12% (5-10% measured); the
// dipoles miss the single scattering near the entry point and Burley's searchlight shape was
// fitted index-matched (24-76% measured).
TEST(ProfileComparison, PhotonBeamDiffusionIsClosestBehindAFresnelBoundary) {
  const ProfileComparison c = compare(skin1(), 200000);
  const double pbd[3] = {c.find(ProfileModel::BeamDiffusion).errors.profileError.x,
                         c.find(ProfileModel::BeamDiffusion).errors.profileError.y,
                         c.find(ProfileModel::BeamDiffusion).errors.profileError.z};
  for (int ch = 0; ch < 3; ++ch) {
    EXPECT_LT(pbd[ch], 0.12) << ch;
    EXPECT_LT(c.noiseFloor[ch], 0.05) << ch;
    for (const ModelComparison& m : c.models) {
      if (m.model != ProfileModel::BeamDiffusion) {
        EXPECT_LT(pbd[ch], m.errors.profileError[ch]) << toString(m.model);
      }
    }
  }
}

// Diffusion is accurate in total at high albedo: index-matched at c = 0.99 the dipole's
// closed form is within 2% of the walk (-0.8% measured) and the better dipole within 3%
// (-2.0%), single scattering included (20% of it there); at c = 0.7 they miss by more than
// 10% (-18% and -42% measured), where single scattering, which diffusion does not describe, is
// over 40% of the reflectance.
TEST(ProfileComparison, DipoleTotalsAreRightAtHighAlbedoOnly) {
  const ProfileComparison c = compare(indexMatched(), 100000);
  const ProfileErrors& dipole = c.find(ProfileModel::Dipole).errors;
  const ProfileErrors& better = c.find(ProfileModel::BetterDipole).errors;
  EXPECT_LT(std::abs(dipole.totalError.z), 0.02);
  EXPECT_LT(std::abs(better.totalError.z), 0.03);
  EXPECT_LT(dipole.totalError.x, -0.10);
  EXPECT_LT(better.totalError.x, -0.10);
  const HalfSpaceWalkResult& low = c.walks[0];
  EXPECT_GT(low.singleReflectance / low.totalReflectance, 0.4);
}

TEST(ProfileComparison, RejectsAnInvalidMedium) {
  ScatteringMedium bad = indexMatched();
  bad.sigmaA.x = -1.0;
  EXPECT_THROW(compareProfilesWithWalk(bad, ProfileComparisonOptions{}), std::invalid_argument);
}

}  // namespace profile_comparison_test
}  // namespace scatterlab
