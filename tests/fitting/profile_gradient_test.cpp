// The subsurface profile kernels as the fitter runs them, checked with ceres::GradientChecker:
// the Jet derivatives of fitRadialAnnuli's and fitRadialProfile's residuals (a profile's
// cumulative reflectance over an annulus, or its value at a radius) against Ridders' numeric
// differences, for Burley's normalised diffusion with its shape factor (the shape-factor fit)
// and with (A, d), Jensen's dipole and d'Eon's better dipole in (sigma_s', sigma_a), and photon
// beam diffusion's multiple- and single-scattering kernels in (rho, g); annuli from r = 0 (where
// R diverges for Burley) out to the tail.
//
// Tolerance, as in kernel_gradient_test.cpp: Ridders' extrapolation started at a relative step
// of 1e-3 (Ceres's default 1e-2 stops early on exponentials) is good to ~1e-10 on these smooth
// functions, and each residual is scaled to O(1) (weight 1 / value at the probe point, data 10%
// off the model) so that Ridders' absolute stopping test (1e-12) does not cut it short; 1e-6
// relative leaves a wide margin and still catches a missed chain-rule factor (an O(1) error).
// Positive parameters enter as their logarithms: Ceres's Ridders steps do not shrink with |x|
// below 1, far too coarse for Marble's sigma_a = 0.0021 (kernel_gradient_test.cpp does the
// same). Photon beam diffusion integrates over depth on nodes placed by the parameters' values
// (its Jets differentiate the integrand at fixed nodes), so its numeric derivative also sees
// the quadrature error (~1e-7 of the value) move with the nodes: 1e-5 there.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <ceres/autodiff_cost_function.h>
#include <ceres/gradient_checker.h>
#include <ceres/manifold.h>

#include "fitting/burley_shape_fit.h"
#include "fitting/radial_profile_fit.h"
#include "materials/bssrdf/better_dipole.h"
#include "materials/bssrdf/dipole.h"
#include "materials/bssrdf/photon_beam_diffusion.h"

namespace scatterlab::fitting {
namespace profile_gradient_test {

constexpr double Precision = 1e-6;
constexpr double QuadraturePrecision = 1e-5;

// A profile with its parameters as logarithms where `logarithmic` says so: p_i = exp(u_i).
template <typename Profile> struct LogParameters {
  static constexpr int ParameterCount = Profile::ParameterCount;
  Profile profile;
  std::array<bool, ParameterCount> logarithmic;
  template <typename T> std::array<T, ParameterCount> parameters(const T* u) const {
    using std::exp;
    std::array<T, ParameterCount> p;
    for (int i = 0; i < ParameterCount; ++i) p[size_t(i)] = logarithmic[size_t(i)] ? exp(u[i]) : u[i];
    return p;
  }
  template <typename T> T cumulative(const T* u, double r) const {
    return profile.cumulative(parameters(u).data(), r);
  }
  template <typename T> T operator()(const T* u, double r) const { return profile(parameters(u).data(), r); }
  std::vector<double> toLogarithms(std::vector<double> p) const {
    for (int i = 0; i < ParameterCount; ++i)
      if (logarithmic[size_t(i)]) p[size_t(i)] = std::log(p[size_t(i)]);
    return p;
  }
};
template <typename Profile> LogParameters<Profile> allLogarithmic(const Profile& profile) {
  LogParameters<Profile> out{profile, {}};
  out.logarithmic.fill(true);
  return out;
}

struct BurleyAlbedoAndLength {
  static constexpr int ParameterCount = 2;  // A, d
  template <typename T> T cumulative(const T* p, double r) const {
    return burleyCumulative(p[0], p[1], T(r));
  }
};

struct JensenDipoleCoefficients {
  static constexpr int ParameterCount = 2;  // sigma_s', sigma_a
  double boundaryFactor = jensenBoundaryFactor(1.3);
  template <typename T> T cumulative(const T* p, double r) const {
    return jensenDipoleCumulative(makeJensenDipole(p[0], p[1], boundaryFactor), T(r));
  }
};

struct BetterDipoleCoefficients {
  static constexpr int ParameterCount = 2;  // sigma_s', sigma_a
  FresnelBoundary boundary = fresnelBoundary(1.4);
  template <typename T> T cumulative(const T* p, double r) const {
    return betterDipoleCumulative(makeBetterDipole(p[0], p[1], boundary), T(r));
  }
};

struct BeamDiffusion {
  static constexpr int ParameterCount = 2;  // rho, g
  FresnelBoundary boundary = fresnelBoundary(1.3);
  template <typename T> T operator()(const T* p, double r) const {
    return beamDiffusionMultiple(p[0], p[1], boundary, r) + beamDiffusionSingle(p[0], p[1], 1.3, r);
  }
};

ceres::NumericDiffOptions riddersOptions() {
  ceres::NumericDiffOptions options;
  options.ridders_relative_initial_step_size = 1e-3;
  return options;
}

// Whether the checker accepts the residual's Jacobian (it must also be finite); `log` gets the
// checker's table.
template <typename Residual, int K>
bool gradientMatches(Residual* residual, std::vector<double> parameters, const std::string& label,
                     double precision = Precision, std::string* log = nullptr) {
  ceres::AutoDiffCostFunction<Residual, 1, K> cost(residual);
  const ceres::GradientChecker checker(
      &cost, static_cast<const std::vector<const ceres::Manifold*>*>(nullptr), riddersOptions());
  ceres::GradientChecker::ProbeResults results;
  double* blocks[] = {parameters.data()};
  const bool ok = checker.Probe(blocks, precision, &results);
  for (const double r : results.residuals) EXPECT_TRUE(std::isfinite(r)) << label;
  if (log)
    *log = "max relative error " + std::to_string(results.maximum_relative_error) + "\n" + results.error_log;
  return ok;
}

template <typename Residual, int K>
void expectGradientMatches(Residual* residual, std::vector<double> parameters, const std::string& label,
                           double precision = Precision) {
  std::string log;
  EXPECT_TRUE((gradientMatches<Residual, K>(residual, std::move(parameters), label, precision, &log)))
      << label << ": " << log;
}

// Annuli from the centre to the tail (mm; mean free paths ~1).
const std::vector<std::pair<double, double>>& annuli() {
  static const std::vector<std::pair<double, double>> a{{0.0, 0.01}, {0.3, 0.35}, {2.0, 2.5}, {10.0, 12.0}};
  return a;
}

template <typename Profile> void expectAnnulusGradients(const Profile& plain,
                                                        const std::vector<double>& parameters,
                                                        const std::string& name) {
  constexpr int K = Profile::ParameterCount;
  const LogParameters<Profile> profile = allLogarithmic(plain);
  const std::vector<double> u = profile.toLogarithms(parameters);
  for (const auto& [r0, r1] : annuli()) {
    const double area = Pi * (r1 * r1 - r0 * r0);
    const double model = (profile.cumulative(u.data(), r1) - profile.cumulative(u.data(), r0)) / area;
    ASSERT_GT(model, 0.0) << name;
    using Residual = detail::RadialAnnulusResidual<LogParameters<Profile>>;
    expectGradientMatches<Residual, K>(new Residual{&profile, r0, r1, area, 1.1 * model, 1.0 / model}, u,
                                       name + " on [" + std::to_string(r0) + ", " + std::to_string(r1) + "]");
  }
}

TEST(ProfileGradients, BurleyShapeFactor) {
  for (const double A : {0.2, 0.8, 0.99}) {
    const BurleyShapeProfile profile{A, 1.0};
    expectAnnulusGradients(profile, {burleyShapeFactor(BurleyFit::Searchlight, A)},
                           "burley s, A " + std::to_string(A));
    expectAnnulusGradients(BurleyPowerAndShapeProfile{1.0},
                           {0.9 * A, burleyShapeFactor(BurleyFit::Searchlight, A)},
                           "burley (P, s), A " + std::to_string(A));
  }
}

TEST(ProfileGradients, BurleyAlbedoAndLength) {
  expectAnnulusGradients(BurleyAlbedoAndLength{}, {0.6, 0.9}, "burley (A, d)");
  expectAnnulusGradients(BurleyAlbedoAndLength{}, {0.3, 3.0}, "burley (A, d) wide");
}

TEST(ProfileGradients, JensenDipole) {
  expectAnnulusGradients(JensenDipoleCoefficients{}, {1.01, 0.48}, "dipole (Skin1 blue)");
  expectAnnulusGradients(JensenDipoleCoefficients{}, {2.19, 0.0021}, "dipole (Marble red)");
}

TEST(ProfileGradients, BetterDipole) {
  expectAnnulusGradients(BetterDipoleCoefficients{}, {1.01, 0.48}, "better dipole (Skin1 blue)");
  expectAnnulusGradients(BetterDipoleCoefficients{}, {2.19, 0.0021}, "better dipole (Marble red)");
}

// The check has power: a kernel whose Jet drops the derivative through d (the value is right)
// is rejected on every annulus.
struct BurleyWithoutLengthDerivative {
  static constexpr int ParameterCount = 2;  // A, d
  template <typename T> T cumulative(const T* p, double r) const {
    return burleyCumulative(p[0], T(scatterlab::detail::valueOf(p[1])), T(r));
  }
};

TEST(ProfileGradients, ADroppedDerivativeIsCaught) {
  const BurleyWithoutLengthDerivative profile;
  const std::vector<double> p{0.6, 0.9};
  for (const auto& [r0, r1] : annuli()) {
    const double area = Pi * (r1 * r1 - r0 * r0);
    const double model = (profile.cumulative(p.data(), r1) - profile.cumulative(p.data(), r0)) / area;
    using Residual = detail::RadialAnnulusResidual<BurleyWithoutLengthDerivative>;
    EXPECT_FALSE((gradientMatches<Residual, 2>(new Residual{&profile, r0, r1, area, 1.1 * model, 1.0 / model},
                                               p, "control")))
        << "[" << r0 << ", " << r1 << "]";
  }
}

TEST(ProfileGradients, PhotonBeamDiffusion) {
  const LogParameters<BeamDiffusion> profile{BeamDiffusion{}, {true, false}};  // log rho, g as it is
  for (const double r : {0.01, 0.5, 4.0})
    for (const std::vector<double>& p : {std::vector<double>{0.9, 0.3}, std::vector<double>{0.5, 0.0}}) {
      const std::vector<double> u = profile.toLogarithms(p);
      const double model = profile(u.data(), r);
      using Residual = detail::RadialPointResidual<LogParameters<BeamDiffusion>>;
      expectGradientMatches<Residual, 2>(new Residual{&profile, r, 1.1 * model, 1.0 / model}, u,
                                         "beam diffusion at r " + std::to_string(r), QuadraturePrecision);
    }
}

}  // namespace profile_gradient_test
}  // namespace scatterlab::fitting
