// A subsurface material: a medium, a diffusion profile built from it, and the boundary the
// renderer puts around it (integrator/subsurface.h). The three ways to give the medium
// (registry: subsurface_registry.h) end here as a ScatteringMedium:
//  - coefficients sigma_s, sigma_a (mm^-1), g, eta, as they are;
//  - a measured medium of Jensen et al. 2001 (measured_media.h): the table's reduced
//    coefficients, sigma_s = sigma_s' / (1 - g) so that the measured sigma_s' is kept;
//  - a diffuse colour (the total diffuse reflectance per channel) and the mean free path
//    1 / sigma_t: the albedo at which the chosen model's total reflectance is the colour
//    (mediumFromReflectance, bisection to 1e-12 in the albedo).
// Burley's normalised diffusion has no medium of its own: from a medium, A is the medium's
// diffuse reflectance as Jensen et al. define and tabulate it (the dipole's closed form, so
// "Skin1" has the paper's reflectance (0.436, 0.227, 0.131) under every profile that uses it),
// and l is the reduced mean free path 1 / sigma_t' (or 1 / sigma_tr for the dmfp fit);
// d = l / s(A). From a colour and mean free path, A is the colour.
#pragma once

#include <memory>
#include <string>

#include "materials/bssrdf/burley.h"
#include "materials/bssrdf/medium.h"
#include "materials/bssrdf/separable_bssrdf.h"

namespace scatterlab {

enum class ProfileModel { Dipole, BetterDipole, BeamDiffusion, Burley };
std::string toString(ProfileModel model);

// The interface of the medium for the later renderer: smooth glass-like, or rough (GGX, with
// the material's roughness) dielectric of relative index eta.
enum class SubsurfaceBoundary { Smooth, Rough };

// The profile of `model` for `medium` (validated). Throws std::invalid_argument when the
// medium does not define one (Burley's dmfp fit needs absorption).
std::shared_ptr<const RadialProfile> makeProfile(ProfileModel model, const ScatteringMedium& medium,
                                                 BurleyFit fit);

// The model's total diffuse reflectance as a function of its albedo for one (g, eta): the
// reduced albedo alpha' for the dipoles and Burley (the dipole's), the single-scattering albedo
// rho for beam diffusion. Increasing; largestTotalReflectance is its value at albedo 1.
double totalReflectanceOfAlbedo(ProfileModel model, double albedo, double g, double eta);
double largestTotalReflectance(ProfileModel model, double g, double eta);

// The medium whose `model` reflects `reflectance` per channel (in [0, largest]) with mean free
// path 1 / sigma_t = meanFreePath (mm, > 0). Throws std::invalid_argument naming the channel
// when a reflectance is out of the model's reach.
ScatteringMedium mediumFromReflectance(ProfileModel model, const Rgb& reflectance, const Rgb& meanFreePath,
                                       double g, double eta);

struct SubsurfaceMaterial {
  ProfileModel model = ProfileModel::Burley;
  BurleyFit burleyFit = BurleyFit::Searchlight;
  ScatteringMedium medium;
  SubsurfaceBoundary boundary = SubsurfaceBoundary::Smooth;
  double roughness = 0.0;  // rough boundary only
  std::shared_ptr<const RadialProfile> profile;

  SeparableBssrdf bssrdf() const { return SeparableBssrdf(profile, medium.eta); }
};

}  // namespace scatterlab
