// The one-dimensional problem of the BSSRDF profiles, with a profile defined here: Christensen
// & Burley 2015's normalised diffusion R(r) = A (e^(-r/d) + e^(-r/(3d))) / (8 pi d r)
// (docs/references.md, "Normalised diffusion (Burley)"), whose integral of 2 pi r R over r is A.
#include <gtest/gtest.h>

#include <ceres/autodiff_cost_function.h>
#include <ceres/gradient_checker.h>
#include <ceres/manifold.h>

#include "fitting/radial_profile_fit.h"
#include "materials/core/math.h"
#include "materials/core/quadrature.h"
#include "materials/core/rng.h"
#include "materials/measured/measurement_synthesis.h"

namespace scatterlab::fitting {
namespace radial_profile_test {

struct BurleyProfile {
  static constexpr int ParameterCount = 2;  // d (mm), A
  template <typename T> T operator()(const T* p, double r) const {
    using std::exp;
    return p[1] * (exp(-r / p[0]) + exp(-r / (3.0 * p[0]))) / (8.0 * Pi * p[0] * r);
  }
  // integral_0^r 2 pi r' R dr' = A (1 - e^(-r/d) / 4 - 3 e^(-r/(3d)) / 4).
  template <typename T> T cumulative(const T* p, double r) const {
    using std::exp;
    return p[1] * (1.0 - 0.25 * exp(-r / p[0]) - 0.75 * exp(-r / (3.0 * p[0])));
  }
};

// Radii from 0.01 to 20 mm, geometrically spaced (the profile spans decades).
std::vector<double> radii() {
  std::vector<double> r;
  for (int i = 0; i < 64; ++i) r.push_back(0.01 * std::pow(2000.0, i / 63.0));
  return r;
}

std::vector<double> tabulate(double d, double a, const std::vector<double>& r) {
  const double p[2] = {d, a};
  std::vector<double> values;
  for (const double x : r) values.push_back(BurleyProfile{}(p, x));
  return values;
}

RadialFitOptions startingFarAway() {
  RadialFitOptions options;
  options.start = {3.0, 0.2};  // the truth is d = 0.8, A = 0.6
  options.lower = {1e-3, 0.0};
  options.upper = {100.0, 1.0};
  return options;
}

// `fit(options)` from the distant start with each weighting recovers the truth (d = 0.8,
// A = 0.6) to 1e-8 relative: the data are noise-free, so only convergence limits the error.
template <typename Fit>
void expectRecoversTheTruth(const Fit& fit, std::initializer_list<RadialWeighting> weightings) {
  for (const RadialWeighting weighting : weightings) {
    RadialFitOptions options = startingFarAway();
    options.weighting = weighting;
    const RadialFitResult result = fit(options);
    EXPECT_TRUE(result.converged) << result.message;
    EXPECT_NEAR(result.parameters[0], 0.8, 1e-8 * 0.8) << int(weighting);
    EXPECT_NEAR(result.parameters[1], 0.6, 1e-8 * 0.6) << int(weighting);
  }
}

TEST(RadialProfile, TheProfileIntegratesToAlbedo) {
  // A check of the test's own profile: the integral of 2 pi r R(r) is A (Christensen & Burley
  // 2015); adaptive Simpson over [0, 60 d], where the tail is below 1e-8 of the total.
  // At r = 0 the integrand's limit is A / (2 d).
  const double p[2] = {0.8, 0.6};
  QuadratureOptions options;
  options.relativeTolerance = 1e-10;
  const double total = adaptiveSimpson(
      [&](double r) { return r > 0 ? 2.0 * Pi * r * BurleyProfile{}(p, r) : 0.6 / (2.0 * 0.8); }, 0.0,
      60.0 * 0.8, options);
  EXPECT_NEAR(total, 0.6, 1e-7);
}

TEST(RadialProfile, GradientCheckOfTheProfileFunctor) {
  using Residual = detail::RadialPointResidual<BurleyProfile>;
  const BurleyProfile profile;
  for (const double r : {0.01, 0.5, 5.0, 20.0}) {
    ceres::AutoDiffCostFunction<Residual, 1, 2> cost(new Residual{&profile, r, 0.1, 1.0});
    ceres::NumericDiffOptions numeric;
    numeric.ridders_relative_initial_step_size = 1e-3;  // as in kernel_gradient_test.cpp
    const ceres::GradientChecker checker(
        &cost, static_cast<const std::vector<const ceres::Manifold*>*>(nullptr), numeric);
    std::vector<double> p{0.8, 0.6};
    double* blocks[] = {p.data()};
    ceres::GradientChecker::ProbeResults results;
    EXPECT_TRUE(checker.Probe(blocks, 1e-6, &results)) << "r " << r << ": " << results.error_log;
  }
}

// Noise-free values are recovered from a distant start, with every weighting; the optimum is
// exact, so only convergence limits the error (1e-8 relative).
TEST(RadialProfile, RecoversDiffusionLengthAndAlbedoFromNoiseFreeValues) {
  const std::vector<double> r = radii();
  const std::vector<double> values = tabulate(0.8, 0.6, r);
  expectRecoversTheTruth(
      [&](const RadialFitOptions& o) { return fitRadialProfile(BurleyProfile{}, r, values, o); },
      {RadialWeighting::Plain, RadialWeighting::Area, RadialWeighting::Relative});
}

// With 2% multiplicative noise and the Relative weighting (whose weights are then the inverse
// noise standard deviations, as the error bars assume), the truth falls within the reported
// error bars at the expected rate: the sum over seeds of the squared standardised errors of
// both parameters (correlated, so this is a loose check next to noise_coverage_test's
// Mahalanobis test) stays within the central 99.9% of chi^2 with 2 x seeds degrees of freedom
// if the parameters were independent; their correlation widens that, so the band is doubled.
TEST(RadialProfile, ErrorBarsCoverTheTruthUnderNoise) {
  const std::vector<double> r = radii();
  const std::vector<double> clean = tabulate(0.8, 0.6, r);
  constexpr int Seeds = 20;
  double sum = 0;
  int within2 = 0;
  for (int seed = 1; seed <= Seeds; ++seed) {
    std::vector<double> noisy = clean;
    CounterRng rng(uint64_t(seed), 0);
    for (double& v : noisy) {
      const double u0 = rng.uniform();
      v *= 1.0 + 0.02 * standardNormal(u0, rng.uniform());
    }
    RadialFitOptions options = startingFarAway();
    options.weighting = RadialWeighting::Relative;
    const RadialFitResult fit = fitRadialProfile(BurleyProfile{}, r, noisy, options);
    ASSERT_TRUE(fit.covarianceAvailable);
    for (int k = 0; k < 2; ++k) {
      const double z = (fit.parameters[size_t(k)] - (k == 0 ? 0.8 : 0.6)) / fit.standardDeviations[size_t(k)];
      sum += z * z;
      within2 += std::abs(z) <= 2.0;
    }
  }
  std::printf(
      "sum of squared standardised errors over %d seeds: %.1f (expected about %d); within 2 sd: %d of %d\n",
      Seeds, sum, 2 * Seeds, within2, 2 * Seeds);
  EXPECT_GT(sum, 0.25 * 2 * Seeds);
  EXPECT_LT(sum, 2.5 * 2 * Seeds);
  EXPECT_GE(within2, int(0.8 * 2 * Seeds));
}

// Annulus averages: [0, 0.01] (where R diverges) and 63 log-spaced annuli to 20 mm, tabulated
// exactly from the cumulative; recovered from a distant start with every weighting.
TEST(RadialProfile, RecoversFromNoiseFreeAnnulusAverages) {
  std::vector<double> edges{0.0};
  for (const double r : radii()) edges.push_back(r);
  const double truth[2] = {0.8, 0.6};
  std::vector<double> means;
  for (size_t k = 0; k + 1 < edges.size(); ++k)
    means.push_back(
        (BurleyProfile{}.cumulative(truth, edges[k + 1]) - BurleyProfile{}.cumulative(truth, edges[k])) /
        (Pi * (sqr(edges[k + 1]) - sqr(edges[k]))));
  expectRecoversTheTruth(
      [&](const RadialFitOptions& o) { return fitRadialAnnuli(BurleyProfile{}, edges, means, o); },
      {RadialWeighting::Plain, RadialWeighting::Area, RadialWeighting::Radius, RadialWeighting::Relative});
}

TEST(RadialProfile, AnnulusInputIsChecked) {
  const std::vector<double> edges{0.0, 0.5, 1.0, 2.0, 4.0}, means{1.0, 0.5, 0.1, 0.01};
  RadialFitOptions options = startingFarAway();
  EXPECT_THROW(fitRadialAnnuli(BurleyProfile{}, std::span(edges).first(4), means, options),
               std::invalid_argument);
  const std::vector<double> unordered{0.0, 1.0, 0.5, 2.0, 4.0};
  EXPECT_THROW(fitRadialAnnuli(BurleyProfile{}, unordered, means, options), std::invalid_argument);
  EXPECT_THROW(
      fitRadialAnnuli(BurleyProfile{}, std::span(edges).first(2), std::span(means).first(1), options),
      std::invalid_argument);
}

TEST(RadialProfile, BadInputIsRefused) {
  const std::vector<double> r = radii();
  const std::vector<double> values = tabulate(0.8, 0.6, r);
  RadialFitOptions options = startingFarAway();
  EXPECT_THROW(fitRadialProfile(BurleyProfile{}, std::span(r).first(1), std::span(values).first(1), options),
               std::invalid_argument);
  EXPECT_THROW(fitRadialProfile(BurleyProfile{}, r, std::span(values).first(10), options),
               std::invalid_argument);
  options.start = {1.0};
  EXPECT_THROW(fitRadialProfile(BurleyProfile{}, r, values, options), std::invalid_argument);
}

}  // namespace radial_profile_test
}  // namespace scatterlab::fitting
