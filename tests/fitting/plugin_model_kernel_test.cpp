// A plugin's model in the fitter (fitting/plugin_model_kernel.h): its registered kernel gives the
// model's values with exact derivatives (fitting/plugin_fit_kernel.h), and without a kernel the
// central differences of the model's own eval agree with them.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>

#include "fitting/plugin_fit_kernel.h"
#include "fitting/plugin_model_kernel.h"
#include "materials/bsdf/phong.h"

namespace scatterlab::fitting {
namespace plugin_model_kernel_test {

// The normalised Phong lobe (materials/bsdf/phong.h, no diffuse term) as a plugin would register
// it: slots exponent, ks.r, ks.g, ks.b.
struct PhongKernel {
  static constexpr int Slots = 4;
  template <typename T> static RgbT<T> eval(const T* s, const Vec3d& wi, const Vec3d& wo) {
    return phongEval(RgbT<T>(T(0)), RgbT<T>(s[1], s[2], s[3]), s[0], wi, wo);
  }
};

std::unique_ptr<BsdfModel> buildPhong(const MaterialParameters& p) {
  return std::make_unique<PhongBsdf>(Rgb(0.0), p.rgb("ks"), p.number("exponent"));
}

MaterialModel phongPlugin(bool withKernel) {
  MaterialModel model{.type = "plugin-phong",
                      .description = "Phong lobe",
                      .citation = "none",
                      .parameters = {numberParameter("exponent", ValueRange::closed(0.0, 10000.0), 30.0, "n"),
                                     rgbParameter("ks", 0.8, "ks")},
                      .build = buildPhong,
                      .plugin = "/plugins/libphong.so"};
  if (withKernel) model.fitKernel = fitKernelFunction<PhongKernel>();
  return model;
}

MaterialParameters phongParameters() {
  MaterialParameters p;
  p.set("exponent", 30.0);
  p.set("ks", Rgb(0.8));
  return p;
}

struct Evaluation {
  std::array<double, 3> value{};
  std::array<double, 12> gradient{};
};

Evaluation evaluate(const PluginModelKernel& kernel, const std::array<double, 4>& slots, const Vec3d& wi,
                    const Vec3d& wo) {
  Evaluation e;
  kernel.eval(slots.data(), wi, wo, e.value.data(), e.gradient.data());
  return e;
}

const Vec3d Wi(0.3, -0.2, 0.9327379053088815);
const Vec3d Wo(-0.25, 0.1, 0.9630680142129111);  // near the mirror direction: cos alpha ~ 0.996

TEST(PluginModelKernel, KernelValueIsTheModelsEval) {
  const MaterialModel model = phongPlugin(true);
  const PluginModelKernel kernel(model, phongParameters());
  EXPECT_EQ(kernel.slots(), 4);
  EXPECT_FALSE(kernel.numericDerivatives());
  const Evaluation e = evaluate(kernel, {50.0, 0.7, 0.5, 0.3}, Wi, Wo);
  const Rgb f = PhongBsdf(Rgb(0.0), Rgb(0.7, 0.5, 0.3), 50.0).eval(Wi, Wo);
  for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(e.value[size_t(c)], f[c]);
  // f is linear in ks: d f_c / d ks_c = f_c / ks_c exactly, and 0 across channels.
  EXPECT_DOUBLE_EQ(e.gradient[0 * 4 + 1], f[0] / 0.7);
  EXPECT_EQ(e.gradient[0 * 4 + 2], 0.0);
}

// Central differences with h = 6e-6 x max(|x|, 1): truncation h^2 |f'''| / 6 and round-off
// eps |f| / h are both below 1e-9 of the gradient's scale here (f''' along the exponent is
// (ln cos alpha)^3 f, tiny near the mirror direction); 1e-7 relative is far above both.
constexpr double NumericGradientTolerance = 1e-7;

TEST(PluginModelKernel, NumericDerivativesAgreeWithTheKernels) {
  const MaterialModel exactModel = phongPlugin(true), numericModel = phongPlugin(false);
  const PluginModelKernel exact(exactModel, phongParameters()), numeric(numericModel, phongParameters());
  EXPECT_TRUE(numeric.numericDerivatives());
  for (const std::array<double, 4>& slots :
       {std::array<double, 4>{50.0, 0.7, 0.5, 0.3}, std::array<double, 4>{3.0, 0.2, 0.9, 0.4},
        std::array<double, 4>{400.0, 1.0, 0.0, 0.5}}) {  // ks at its bounds
    const Evaluation a = evaluate(exact, slots, Wi, Wo), b = evaluate(numeric, slots, Wi, Wo);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(b.value[size_t(c)], a.value[size_t(c)], 1e-14 * std::abs(a.value[size_t(c)]));
      double scale = 0;
      for (int i = 0; i < 4; ++i) scale = std::max(scale, std::abs(a.gradient[size_t(c * 4 + i)]));
      for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(b.gradient[size_t(c * 4 + i)], a.gradient[size_t(c * 4 + i)],
                    NumericGradientTolerance * scale)
            << "exponent " << slots[0] << ", channel " << c << ", slot " << i;
    }
  }
}

}  // namespace plugin_model_kernel_test
}  // namespace scatterlab::fitting
