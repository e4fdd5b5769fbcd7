// The separable BSSRDF's directional term as the renderer's exit-point BSDF
// (subsurface_exit_bsdf.h), through the kit: cosine sampling against its pdf (chi-square),
// sample weight = f |cos| / pdf, pdf normalisation, and albedo 1 (its normalisation c) at every
// incident angle. 200,000 samples per angle on the kit's default grid: the chi-square and
// furnace tolerances are the kit's own (Sidak-corrected significance 0.01).
#include <gtest/gtest.h>

#include "materials/bssrdf/subsurface_exit_bsdf.h"
#include "validation/bsdf_check.h"

namespace scatterlab {
namespace subsurface_exit_bsdf_test {

TEST(SubsurfaceExitBsdf, PassesTheKitAndIsLossless) {
  for (const double eta : {1.0, 1.3, 1.5}) {
    const SubsurfaceExitBsdf model(eta);
    BsdfCheckOptions o;
    o.samples = 200'000;
    o.wiThetaDeg = {0, 60};
    o.reciprocityPairs = 0;
    const CheckReport report = runBsdfChecks(model, "exit eta " + std::to_string(eta), o);
    for (const CheckRow& row : report.rows)
      EXPECT_TRUE(row.passed) << "eta " << eta << ": " << row.test << " at " << row.wiThetaDeg.value_or(-1)
                              << ": " << row.note;
  }
}

// f depends on wo alone: Sw(wo) = (1 - F(cos theta_o)) / (pi c), whatever wi.
TEST(SubsurfaceExitBsdf, IsTheDirectionalTerm) {
  const SubsurfaceExitBsdf model(1.4);
  const double c = separableNormalization(1.4);
  const Vec3d wo = glm::normalize(Vec3d(0.3, -0.2, 0.5));
  for (const Vec3d& wi : {Vec3d(0, 0, 1), glm::normalize(Vec3d(0.7, 0.1, 0.2))})
    EXPECT_DOUBLE_EQ(model.eval(wi, wo).x, separableDirectional(wo.z, 1.4, c));
  EXPECT_EQ(model.eval(Vec3d(0, 0, 1), Vec3d(0, 0, -1)), Rgb(0.0));
}

}  // namespace subsurface_exit_bsdf_test
}  // namespace scatterlab
