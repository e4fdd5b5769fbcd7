// The test's size: a correct sampler must be rejected at rate ~alpha over many seeds, and
// its p-values must be uniform. (A test that rarely rejects correct samplers but never
// rejects wrong ones is useless; negative_controls_test.cpp covers the other side.) The
// catalog's models run the same study in tests/materials/bsdf/seed_study_test.cpp.
#include <gtest/gtest.h>

#include "materials/bsdf/lambertian.h"
#include "validation/bsdf_sampling.h"
#include "validation/seed_study.h"

namespace scatterlab {
namespace false_rejection_test {

TEST(FalseRejection, RateMatchesSignificanceAndPValuesAreUniform) {
  const LambertianBsdf model(Rgb(0.6));
  const Vec3d wi = directionFromDegrees(35, 20);
  const SeedStudyResult study = repeatedSeedStudy(
      bsdfDirectionSampler(model, wi),
      [&](const Vec3d& wo) { return model.pdf(wi, wo, TransportMode::Radiance); }, SphericalGrid{16, 32},
      20000, 400, 0.05, 1000);
  // Binomial(400, 0.05): mean 20, sd 4.36; accept within 3.5 sd.
  EXPECT_LT(std::abs(study.rejectionZ()), 3.5) << study.rejected << " rejections in " << study.runs;
  // Kolmogorov-Smirnov against U(0, 1): D_crit(n = 400, 0.001) = 1.95 / sqrt(400) = 0.0976.
  EXPECT_LT(study.ksDistance(), 1.95 / std::sqrt(double(study.runs)))
      << "KS distance of p-values from uniform";
}

}  // namespace false_rejection_test
}  // namespace scatterlab
