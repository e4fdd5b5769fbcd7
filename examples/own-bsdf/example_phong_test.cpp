// The example's model checked by scatterlab's test kit from a GoogleTest (validation/gtest_check.h):
// it passes every check and the negative controls, and a variant whose pdf uses an exponent 10%
// off the sampler's is rejected, which shows that the kit at these settings can tell.
#include <gtest/gtest.h>

#include "example_phong.h"
#include "validation/gtest_check.h"

namespace {

using own_bsdf::ExamplePhong;
using scatterlab::Rgb;

TEST(ExamplePhong, PassesTheKitWithNegativeControls) {
  const ExamplePhong model(Rgb(0.8), 30.0);
  // The roughness-mismatch control samples from the same lobe with its exponent 10% off.
  const ExamplePhong mismatched(Rgb(0.8), 30.0 / 1.1);
  scatterlab::CheckBsdfOptions options;
  options.label = "example-phong";
  options.negativeControls = true;
  options.roughnessMismatchSampler = &mismatched;
  EXPECT_TRUE(scatterlab::passesBsdfCheck(model, options));
}

TEST(ExamplePhong, KitRejectsAPdfWithItsExponent10PercentOff) {
  const ExamplePhong broken(Rgb(0.8), 30.0, /*pdfExponentScale=*/1.1);
  scatterlab::CheckBsdfOptions options;
  options.label = "example-phong, pdf exponent 10% off";
  EXPECT_TRUE(scatterlab::failsBsdfCheck(broken, options));
}

}  // namespace
