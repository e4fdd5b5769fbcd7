// Every diffusion profile against the ground truth (docs/validation.md section 6):
// for one medium, the half-space random walk per channel (normal incidence, the medium's g and
// eta) and the four models built from the same medium, compared by
//  - the r-weighted relative error of R(r): the L1 distance between the radial distributions
//    of exitant power, relative to the walk's total (annulus_profile.h), on log-spaced annuli
//    plus the power beyond them;
//  - the relative error of the total diffuse reflectance, with the walk's standard error;
// each against the walk of all orders and against its multiple scattering only (paths that
// scattered at least twice): the dipoles model multiple scattering (Jensen et al. 2001 add
// single scattering as a separate term; d'Eon 2012's alpha'^2 prefactor counts the light that
// scatters at least twice: Grosjean's diffusion source), while photon beam diffusion and
// Burley's fit include single scattering.
#pragma once

#include <array>
#include <vector>

#include "materials/bssrdf/subsurface_material.h"
#include "validation/half_space_reference.h"

namespace scatterlab {

struct ProfileComparisonOptions {
  uint64_t paths = 1'000'000;  // per channel
  uint64_t seed = 1;
  int threads = 0;
  int annuli = 24;  // log-spaced, after [0, first] (`scatterlab profile --bins`)
  BurleyFit burleyFit = BurleyFit::Searchlight;
};

struct ProfileErrors {
  Rgb total{0.0};               // the model's total diffuse reflectance
  Rgb totalError{0.0};          // (model - walk) / walk, all orders
  Rgb profileError{0.0};        // r-weighted relative error of R(r), all orders
  Rgb multipleTotalError{0.0};  // the same against the walk's multiple scattering only
  Rgb multipleProfileError{0.0};
};

struct ModelComparison {
  ProfileModel model = ProfileModel::Dipole;
  ProfileErrors errors;
};

struct ProfileComparison {
  ScatteringMedium medium;
  std::vector<double> edges;  // annuli (mm): 0, then `annuli` log-spaced edges
  std::array<HalfSpaceWalkResult, 3> walks;
  Rgb walkTotal{0.0}, walkStdError{0.0};                  // all orders
  Rgb walkMultipleTotal{0.0}, walkMultipleStdError{0.0};  // scattered at least twice
  Rgb noiseFloor{0.0};  // what the walk's noise alone reads as a profile error (radialNoiseFloor)
  std::vector<ModelComparison> models;  // dipole, better-dipole, beam-diffusion, burley

  const ModelComparison& find(ProfileModel model) const;
};

// The edges reach twice the largest radius that holds 99.9% of any model's profile in any
// channel; 1/1000 of that is the first. Throws std::invalid_argument for an invalid medium.
ProfileComparison compareProfilesWithWalk(const ScatteringMedium& medium,
                                          const ProfileComparisonOptions& options,
                                          const WalkProgress& progress = {});

}  // namespace scatterlab
