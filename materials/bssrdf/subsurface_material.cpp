#include "materials/bssrdf/subsurface_material.h"

#include <cmath>
#include <stdexcept>

#include "materials/bssrdf/beam_diffusion_profile.h"
#include "materials/bssrdf/better_dipole.h"
#include "materials/bssrdf/dipole.h"
#include "materials/core/root_finding.h"

namespace scatterlab {

namespace {

constexpr double AlbedoTolerance = 1e-12;

std::shared_ptr<const RadialProfile> makeBurley(const ScatteringMedium& medium, BurleyFit fit) {
  const double boundary = jensenBoundaryFactor(medium.eta);
  const Rgb alphaPrime = medium.reducedAlbedo(), sigmaTPrime = medium.reducedExtinction();
  Rgb albedo, shape;
  for (int c = 0; c < 3; ++c) {
    albedo[c] = jensenDipoleTotal(alphaPrime[c], boundary);
    double length = 1.0 / sigmaTPrime[c];
    if (fit == BurleyFit::SearchlightDiffuseMfp) {
      const double sigmaTr = std::sqrt(3.0 * medium.sigmaA[c] * sigmaTPrime[c]);
      if (!(sigmaTr > 0))
        throw std::invalid_argument(
            "Burley's diffuse-mean-free-path fit needs absorption (sigma_a > 0) in every channel");
      length = 1.0 / sigmaTr;
    }
    shape[c] = length / burleyShapeFactor(fit, albedo[c]);
  }
  return std::make_shared<BurleyProfile>(albedo, shape);
}

}  // namespace

std::string toString(ProfileModel model) {
  switch (model) {
    case ProfileModel::Dipole: return "dipole";
    case ProfileModel::BetterDipole: return "better-dipole";
    case ProfileModel::BeamDiffusion: return "beam-diffusion";
    case ProfileModel::Burley: return "burley";
  }
  return "unknown";
}

std::shared_ptr<const RadialProfile> makeProfile(ProfileModel model, const ScatteringMedium& medium,
                                                 BurleyFit fit) {
  medium.validate();
  switch (model) {
    case ProfileModel::Dipole:
      return std::make_shared<JensenDipoleProfile>(medium.reducedScattering(), medium.sigmaA, medium.eta);
    case ProfileModel::BetterDipole:
      return std::make_shared<BetterDipoleProfile>(medium.reducedScattering(), medium.sigmaA, medium.eta);
    case ProfileModel::BeamDiffusion: return std::make_shared<BeamDiffusionProfile>(medium);
    case ProfileModel::Burley: return makeBurley(medium, fit);
  }
  throw std::logic_error("unhandled profile model");
}

double totalReflectanceOfAlbedo(ProfileModel model, double albedo, double g, double eta) {
  switch (model) {
    case ProfileModel::Dipole:
    case ProfileModel::Burley: return jensenDipoleTotal(albedo, jensenBoundaryFactor(eta));
    case ProfileModel::BetterDipole:
      // Dimensionless: with sigma_t' = 1 the total depends on alpha' and eta alone.
      return betterDipoleTotal(makeBetterDipole(albedo, 1.0 - albedo, fresnelBoundary(eta)));
    case ProfileModel::BeamDiffusion: return BeamDiffusionTable::shared(g, eta)->effectiveAlbedo(albedo);
  }
  throw std::logic_error("unhandled profile model");
}

double largestTotalReflectance(ProfileModel model, double g, double eta) {
  return totalReflectanceOfAlbedo(model, 1.0, g, eta);
}

ScatteringMedium mediumFromReflectance(ProfileModel model, const Rgb& reflectance, const Rgb& meanFreePath,
                                       double g, double eta) {
  ScatteringMedium medium;
  medium.g = g;
  medium.eta = eta;
  const double largest = largestTotalReflectance(model, g, eta);
  for (int c = 0; c < 3; ++c) {
    if (!(reflectance[c] >= 0) || reflectance[c] > largest + 1e-12)
      throw std::invalid_argument("channel " + std::to_string(c) + ": reflectance " +
                                  std::to_string(reflectance[c]) + " is beyond what " + toString(model) +
                                  " reflects at albedo 1 (" + std::to_string(largest) + ")");
    if (!(meanFreePath[c] > 0) || !std::isfinite(meanFreePath[c]))
      throw std::invalid_argument("channel " + std::to_string(c) +
                                  ": the mean free path must be positive and finite");
    const double albedo =
        bisectIncreasing([&](double a) { return totalReflectanceOfAlbedo(model, a, g, eta); }, reflectance[c],
                         0.0, 1.0, AlbedoTolerance);
    const double sigmaT = 1.0 / meanFreePath[c];
    if (model == ProfileModel::BeamDiffusion) {
      // The table's albedo is the single-scattering one (optical units of sigma_t).
      medium.sigmaS[c] = albedo * sigmaT;
      medium.sigmaA[c] = (1.0 - albedo) * sigmaT;
    } else {
      // alpha' is reduced: sigma_t = sigma_a + sigma_s' / (1 - g) = sigma_t' (1 - alpha' + alpha' / (1 - g)).
      const double sigmaTPrime = sigmaT / (1.0 - albedo + albedo / (1.0 - g));
      medium.sigmaS[c] = albedo * sigmaTPrime / (1.0 - g);
      medium.sigmaA[c] = (1.0 - albedo) * sigmaTPrime;
    }
  }
  return medium;
}

}  // namespace scatterlab
