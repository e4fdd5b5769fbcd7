// Every kernel the fitter differentiates, checked with ceres::GradientChecker: the Jet
// derivatives of the shape slots against central differences, at ordinary, near-specular and
// grazing geometry and at the small end of the roughness range (docs/design.md, "One model code":
// value and derivative must stay finite at singular points).
//
// Tolerance: GradientChecker differentiates numerically by Ridders' extrapolation and compares
// each Jacobian entry relative to the larger of the two derivatives. Started at a relative step
// of 1e-3 (Ceres's default 1e-2 is too coarse for the exponential lobes: its first
// extrapolations already stop with errors of 1e-6), Ridders' estimate is good to ~1e-12 on
// these smooth functions; 1e-6 leaves a wide margin and still catches a wrong derivative (a
// missed chain-rule factor is an O(1) error).
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include <ceres/autodiff_cost_function.h>
#include <ceres/gradient_checker.h>
#include <ceres/manifold.h>

#include "fitting/lobe_kernels.h"
#include "materials/measured/half_diff.h"

namespace scatterlab::fitting {
namespace kernel_gradient_test {

constexpr double Precision = 1e-6;

ceres::NumericDiffOptions riddersOptions() {
  ceres::NumericDiffOptions options;
  options.ridders_relative_initial_step_size = 1e-3;
  return options;
}

// A kernel's terms and rest, flattened, as a function of its slots: log f where f > 0 at the
// probe point (else f). Exponential lobes (cos^n with n up to 1e5, Beckmann's exp(-tan^2/a^2))
// are then close to linear in their parameters, so Ridders' estimate stays accurate where f
// itself changes by decades within a step; and the values are O(1), which Ridders' absolute
// stopping test (1e-12) needs. d log f = df / f, so the Jet's df is what is checked. Values
// below 1e-200 (deep in a lobe's tail, where f's derivative underflows in double arithmetic)
// are held at 0 and not compared. Positive slots enter as their logarithms (x = exp(u)), so
// that the numeric steps are relative to them: Ceres's Ridders steps do not shrink with |x|
// below 1, far too coarse for alpha = 0.001.
template <typename Kernel> struct KernelResiduals {
  static constexpr int Outputs = 3 * (Kernel::Terms + 1);
  Kernel kernel;
  Vec3d wi, wo;
  enum class Form { Value, Logarithm, Dropped };
  std::array<Form, Outputs> form{};
  std::array<bool, Kernel::Slots> logSlot{};

  // `slots` holds the kernel's slots on input and the checked parameters on output.
  KernelResiduals(const Kernel& k, const Vec3d& in, const Vec3d& out, double* slots)
      : kernel(k), wi(in), wo(out) {
    for (int i = 0; i < Kernel::Slots; ++i) {
      logSlot[size_t(i)] = slots[i] > 0;
      if (slots[i] > 0) slots[i] = std::log(slots[i]);
    }
    std::array<double, Outputs> values;
    (*this)(slots, values.data());
    for (int i = 0; i < Outputs; ++i) {
      const double v = values[size_t(i)];
      form[size_t(i)] = v > 1e-200 ? Form::Logarithm : v > 0 ? Form::Dropped : Form::Value;
    }
  }

  template <typename T> bool operator()(const T* parameters, T* out) const {
    using std::exp;
    using std::log;
    std::array<T, Kernel::Slots> slots;
    for (int i = 0; i < Kernel::Slots; ++i)
      slots[size_t(i)] = logSlot[size_t(i)] ? exp(parameters[i]) : parameters[i];
    std::array<RgbT<T>, (Kernel::Terms > 0 ? Kernel::Terms : 1)> terms;
    RgbT<T> rest;
    kernel.eval(slots.data(), wi, wo, terms.data(), rest);
    for (int j = 0; j <= Kernel::Terms; ++j)
      for (int c = 0; c < 3; ++c) {
        const T& v = j < Kernel::Terms ? terms[size_t(j)][c] : rest[c];
        const size_t i = size_t(3 * j + c);
        out[i] = form[i] == Form::Logarithm ? log(v) : form[i] == Form::Dropped ? T(0) : v;
      }
    return true;
  }
};

struct Geometry {
  std::string name;
  Vec3d wi, wo;
};

Vec3d direction(double thetaDeg, double phiDeg) { return directionFromDegrees(thetaDeg, phiDeg); }

Geometry halfDiff(std::string name, double thetaHalf, double thetaDiff, double phiDiff) {
  const auto [wi, wo] = directionsFromHalfDiff(thetaHalf, 0.0, thetaDiff, phiDiff);
  return {std::move(name), wi, wo};
}

// Ordinary, off-highlight, near the mirror direction, and grazing geometry.
std::vector<Geometry> geometries() {
  return {{"ordinary", direction(30, 0), direction(50, 160)},
          {"near mirror", direction(40, 10), direction(41, 191)},
          halfDiff("highlight", 0.02, 0.6, 1.0),
          {"grazing wi", direction(89.9, 0), direction(45, 180)},
          {"grazing both", direction(89.9, 0), direction(89.5, 178)},
          {"retro", direction(70, 20), direction(69, 25)}};
}

template <typename Kernel> void expectGradientsMatch(const Kernel& kernel, const std::vector<double>& slots,
                                                     const std::string& label,
                                                     const std::vector<Geometry>& where = geometries()) {
  for (const Geometry& g : where) {
    using Residuals = KernelResiduals<Kernel>;
    std::vector<double> parameters = slots;
    ceres::AutoDiffCostFunction<Residuals, Residuals::Outputs, Kernel::Slots> cost(
        new Residuals(kernel, g.wi, g.wo, parameters.data()));
    const ceres::GradientChecker checker(
        &cost, static_cast<const std::vector<const ceres::Manifold*>*>(nullptr), riddersOptions());
    ceres::GradientChecker::ProbeResults results;
    std::vector<double*> blocks{parameters.data()};
    EXPECT_TRUE(checker.Probe(blocks.data(), Precision, &results))
        << label << " at " << g.name << ": max relative error " << results.maximum_relative_error << "\n"
        << results.error_log;
    for (const double r : results.residuals) EXPECT_TRUE(std::isfinite(r)) << label << " at " << g.name;
  }
}

TEST(KernelGradients, OrenNayar) {
  expectGradientsMatch(OrenNayarKernel{}, {0.35}, "oren-nayar sigma 0.35");
  expectGradientsMatch(OrenNayarKernel{}, {1.4}, "oren-nayar sigma 1.4");
}

TEST(KernelGradients, Eon) {
  EonKernel fitted, analytic;
  analytic.albedoMode = EonAlbedo::Analytic;
  expectGradientsMatch(fitted, {0.8, 0.5, 0.2, 0.5}, "eon fitted");
  expectGradientsMatch(analytic, {0.8, 0.5, 0.2, 0.05}, "eon analytic, small roughness");
}

TEST(KernelGradients, PhongAndBlinnPhong) {
  for (const double n : {2.0, 150.0, 5000.0}) {
    expectGradientsMatch(NormalizedPhongKernel<PhongLobe>{}, {n}, "phong n " + std::to_string(n));
    expectGradientsMatch(NormalizedPhongKernel<BlinnPhongLobe>{}, {n}, "blinn-phong n " + std::to_string(n));
  }
}

// Ngan's normalisation divides by max(|Cx|, |Cy|, |Cz|), which has no derivative where two of
// them tie; the slots are probed off the ties (the fitter's tied Cx = Cy sums both partial
// derivatives, which is the derivative along the tie: least_squares_test.cpp checks it).
TEST(KernelGradients, Lafortune) {
  LafortuneKernel ngan, raw;
  raw.normalization = LafortuneNormalization::None;
  expectGradientsMatch(ngan, {-0.9, -0.7, 0.8, 30.0}, "lafortune ngan, Cx the largest");
  expectGradientsMatch(ngan, {-0.6, -0.7, 0.95, 3000.0}, "lafortune ngan sharp, Cz the largest");
  expectGradientsMatch(raw, {-0.7, -0.8, 0.6, 8.0}, "lafortune none");
}

// Microfacet lobes at ordinary roughness, and at the registry's smallest alpha 0.001 with
// geometry around its highlight (theta_h of 0.5 and 2 alpha: the peak and the steep flank).
std::vector<Geometry> tinyRoughnessGeometries() {
  return {halfDiff("peak", 0.0005, 0.4, 0.5), halfDiff("flank", 0.002, 0.4, 0.5),
          halfDiff("grazing peak", 0.0005, 1.55, 0.5)};
}

TEST(KernelGradients, Ward) {
  expectGradientsMatch(WardKernel{}, {0.2, 0.2}, "ward 0.2");
  expectGradientsMatch(WardKernel{}, {0.05, 0.3}, "ward anisotropic");
  expectGradientsMatch(WardKernel{}, {0.001, 0.001}, "ward 0.001", tinyRoughnessGeometries());
  expectGradientsMatch(NganWardKernel{}, {0.15}, "ngan-ward 0.15");
  expectGradientsMatch(NganWardKernel{}, {0.001}, "ngan-ward 0.001", tinyRoughnessGeometries());
}

TEST(KernelGradients, AshikhminShirley) {
  expectGradientsMatch(AshikhminShirleyKernel{}, {100.0, 100.0, 0.05, 0.04, 0.03}, "ashikhmin-shirley");
  expectGradientsMatch(AshikhminShirleyKernel{}, {10.0, 1000.0, 0.9, 0.5, 0.2},
                       "ashikhmin-shirley anisotropic");
  expectGradientsMatch(NganAshikhminShirleyKernel{}, {0.3, 500.0}, "ngan-ashikhmin-shirley");
  expectGradientsMatch(NganAshikhminShirleyKernel{}, {0.05, 90000.0}, "ngan-ashikhmin-shirley sharp",
                       tinyRoughnessGeometries());
}

TEST(KernelGradients, NganCookTorrance) {
  expectGradientsMatch(NganCookTorranceKernel{}, {0.2, 0.1}, "cook-torrance 0.1");
  expectGradientsMatch(NganCookTorranceKernel{}, {0.9, 0.6}, "cook-torrance 0.6");
  expectGradientsMatch(NganCookTorranceKernel{}, {0.1, 0.001}, "cook-torrance 0.001",
                       tinyRoughnessGeometries());
}

TEST(KernelGradients, Conductor) {
  ConductorKernel<GgxDistribution> ggxWhite;
  ConductorKernel<BeckmannDistribution> beckmannWhite;
  ConductorKernel<GgxDistribution> gold;
  gold.eta = Rgb(0.143, 0.374, 1.442);
  gold.k = Rgb(3.983, 2.385, 1.603);
  for (const double alpha : {0.05, 0.3, 1.0}) {
    expectGradientsMatch(ggxWhite, {alpha, alpha}, "ggx white " + std::to_string(alpha));
    expectGradientsMatch(beckmannWhite, {alpha, alpha}, "beckmann white " + std::to_string(alpha));
  }
  expectGradientsMatch(gold, {0.2, 0.07}, "ggx gold anisotropic");
  expectGradientsMatch(ggxWhite, {0.001, 0.001}, "ggx 0.001", tinyRoughnessGeometries());
  expectGradientsMatch(beckmannWhite, {0.001, 0.001}, "beckmann 0.001", tinyRoughnessGeometries());
}

// The conductor with its index fitted: the derivatives through (f0, edge tint) -> (eta, k),
// inside the family, a copper-like and a dielectric-like point. The tints stay a few per cent
// below 1: at 1 the family ends (k^2 reaches 0, where sqrt has no derivative), and Ridders'
// first steps (percents of the parameter) must not cross it. Not at retro-reflection: there
// wi . h ~ 1, where F is f0 whatever the tint, so the tint's derivative is 1e-8 of the value,
// round-off that no relative comparison can judge.
TEST(KernelGradients, ConductorWithFittedIndex) {
  std::vector<Geometry> where = geometries();
  std::erase_if(where, [](const Geometry& g) { return g.name == "retro"; });
  expectGradientsMatch(FittedIndexConductorKernel<GgxDistribution>{},
                       {0.2, 0.2, 0.93, 0.64, 0.53, 0.95, 0.9, 0.85}, "ggx copper-like index", where);
  expectGradientsMatch(FittedIndexConductorKernel<BeckmannDistribution>{},
                       {0.3, 0.1, 0.05, 0.04, 0.06, 0.3, 0.5, 0.7}, "beckmann dielectric-like index", where);
}

// Every lobe on (sheen, clearcoat, metallic between 0 and 1), so every slot matters. Not at
// retro-reflection: there the sheen's weight (1 - cos theta_d)^5 is below 1e-8, and the
// sheen's derivatives are round-off that no relative comparison can judge.
TEST(KernelGradients, Disney) {
  std::vector<Geometry> where = geometries();
  std::erase_if(where, [](const Geometry& g) { return g.name == "retro"; });
  const std::vector<double> slots{0.6, 0.4, 0.1, 0.3, 0.4, 0.5, 0.3, 0.4, 0.2, 0.5, 0.4, 0.6, 0.7};
  expectGradientsMatch(DisneyKernel{}, slots, "disney", where);
  std::vector<double> smooth = slots;
  smooth[7] = 0.05;  // roughness 0.05: alpha 0.0025
  expectGradientsMatch(DisneyKernel{}, smooth, "disney smooth", where);
}

}  // namespace kernel_gradient_test
}  // namespace scatterlab::fitting
