// The profile kernels are templated for the fitter's ceres::Jet (docs/design.md, "One model code"):
// each is instantiated with Jets here, and its derivatives are compared with central finite
// differences of the double kernel (what ceres::GradientChecker does), including at the
// guarded points (no absorption: sigma_tr = 0; Burley at r = 0).
#include <gtest/gtest.h>

#include <ceres/jet.h>

#include <functional>
#include <vector>

#include "materials/bssrdf/better_dipole.h"
#include "materials/bssrdf/burley.h"
#include "materials/bssrdf/dipole.h"
#include "materials/bssrdf/photon_beam_diffusion.h"
#include "materials/bssrdf/separable_bssrdf.h"

namespace scatterlab {
namespace profile_autodiff_test {

constexpr int N = 2;
using Jet = ceres::Jet<double, N>;

// f evaluated with Jets at x (each parameter seeded with its own derivative) against central
// differences with step h x_i: truncation ~h^2, round-off ~1e-16 / h.
void expectGradient(const std::function<Jet(const Jet&, const Jet&)>& f, double x0, double x1,
                    double h = 1e-5, double tolerance = 1e-6) {
  const Jet value = f(Jet(x0, 0), Jet(x1, 1));
  ASSERT_TRUE(std::isfinite(value.a));
  const double x[2] = {x0, x1};
  for (int i = 0; i < N; ++i) {
    ASSERT_TRUE(std::isfinite(value.v[i])) << "parameter " << i;
    const double step = h * std::max(std::abs(x[i]), 1e-3);
    double up[2] = {x0, x1}, down[2] = {x0, x1};
    up[i] += step;
    down[i] -= step;
    const double numeric = (f(Jet(up[0]), Jet(up[1])).a - f(Jet(down[0]), Jet(down[1])).a) / (2 * step);
    EXPECT_NEAR(value.v[i], numeric, tolerance * std::max(std::abs(numeric), 1e-8)) << "parameter " << i;
  }
}

TEST(ProfileAutodiff, JensenDipole) {
  const double A = jensenBoundaryFactor(1.3);
  for (const double r : {0.0, 0.3, 2.0}) {
    expectGradient(
        [&](const Jet& s, const Jet& a) { return jensenDipoleProfile(makeJensenDipole(s, a, A), Jet(r)); },
        1.2, 0.05);
    expectGradient(
        [&](const Jet& s, const Jet& a) { return jensenDipoleCumulative(makeJensenDipole(s, a, A), Jet(r)); },
        1.2, 0.05);
  }
  expectGradient([&](const Jet& alphaPrime, const Jet&) { return jensenDipoleTotal(alphaPrime, A); }, 0.8,
                 0.0);
}

TEST(ProfileAutodiff, BetterDipole) {
  const FresnelBoundary b = fresnelBoundary(1.4);
  for (const double r : {0.0, 0.3, 2.0}) {
    expectGradient(
        [&](const Jet& s, const Jet& a) { return betterDipoleProfile(makeBetterDipole(s, a, b), Jet(r)); },
        0.9, 0.02);
    expectGradient(
        [&](const Jet& s, const Jet& a) { return betterDipoleCumulative(makeBetterDipole(s, a, b), Jet(r)); },
        0.9, 0.02);
  }
  expectGradient([&](const Jet& s, const Jet& a) { return betterDipoleTotal(makeBetterDipole(s, a, b)); },
                 0.9, 0.02);
}

TEST(ProfileAutodiff, GuardsKeepDerivativesFiniteWithoutAbsorption) {
  // sigma_a = 0: sigma_tr = sqrt(0) would have an infinite slope; safeSqrt gives 0 there.
  const FresnelBoundary b = fresnelBoundary(1.3);
  const Jet total = betterDipoleTotal(makeBetterDipole(Jet(1.0, 0), Jet(0.0, 1), b));
  EXPECT_NEAR(total.a, 1.0, 1e-14);
  EXPECT_TRUE(std::isfinite(total.v[0]) && std::isfinite(total.v[1]));
  const Jet dipole = jensenDipoleTotal(Jet(1.0, 0), jensenBoundaryFactor(1.3));
  EXPECT_TRUE(std::isfinite(dipole.v[0]));
  const Jet burleyAtZero = burleyProfile(Jet(0.5, 0), Jet(1.0, 1), Jet(0.0));
  EXPECT_TRUE(std::isfinite(burleyAtZero.a) && std::isfinite(burleyAtZero.v[0]) &&
              std::isfinite(burleyAtZero.v[1]));
}

TEST(ProfileAutodiff, BurleyWithItsShapeFactor) {
  // The fitter's problem: A and the length l, with d = l / s(A) for each fit.
  for (const BurleyFit fit :
       {BurleyFit::Searchlight, BurleyFit::DiffuseTransmission, BurleyFit::SearchlightDiffuseMfp})
    for (const double r : {0.01, 0.5, 3.0})
      expectGradient(
          [&](const Jet& A, const Jet& l) { return burleyProfile(A, l / burleyShapeFactor(fit, A), Jet(r)); },
          0.6, 1.3);
  expectGradient([](const Jet& A, const Jet& d) { return burleyCumulative(A, d, Jet(0.7)); }, 0.6, 1.3);
}

TEST(ProfileAutodiff, PhotonBeamDiffusionKernels) {
  const FresnelBoundary b = fresnelBoundary(1.3);
  for (const double r : {0.01, 1.0}) {
    expectGradient([&](const Jet& rho, const Jet& g) { return beamDiffusionMultiple(rho, g, b, r); }, 0.9,
                   0.3);
    expectGradient([&](const Jet& rho, const Jet& g) { return beamDiffusionSingle(rho, g, 1.3, r); }, 0.9,
                   0.3);
  }
  expectGradient([](const Jet& rho, const Jet& g) { return beamDiffusionSingleLimit(rho, g, 1.3); }, 0.9,
                 0.3);
}

TEST(ProfileAutodiff, PhaseFunctionAndDirectionalTerm) {
  expectGradient([](const Jet& mu, const Jet& g) { return henyeyGreenstein(mu, g); }, 0.3, 0.6);
  const double c = separableNormalization(1.3);
  expectGradient([&](const Jet& mu, const Jet&) { return separableDirectional(mu, 1.3, c); }, 0.4, 0.0);
}

}  // namespace profile_autodiff_test
}  // namespace scatterlab
