// A homogeneous scattering medium, per linear-RGB channel, and the derived quantities the
// diffusion models use (bssrdf.h conventions: mm, mm^-1).
#pragma once

#include <stdexcept>
#include <string>

#include "materials/core/math.h"

namespace scatterlab {

struct ScatteringMedium {
  Rgb sigmaS{0.0};   // scattering coefficient, mm^-1
  Rgb sigmaA{0.0};   // absorption coefficient, mm^-1
  double g = 0.0;    // Henyey-Greenstein mean cosine, in (-1, 1)
  double eta = 1.3;  // index of refraction inside relative to outside

  Rgb extinction() const { return sigmaS + sigmaA; }
  // sigma_s / sigma_t: the single-scattering albedo the random walk uses.
  Rgb albedo() const { return ratio(sigmaS, extinction()); }
  // sigma_s' = sigma_s (1 - g), sigma_t' = sigma_a + sigma_s', alpha' = sigma_s' / sigma_t'
  // (the similarity relation the diffusion models are written in).
  Rgb reducedScattering() const { return sigmaS * (1.0 - g); }
  Rgb reducedExtinction() const { return sigmaA + reducedScattering(); }
  Rgb reducedAlbedo() const { return ratio(reducedScattering(), reducedExtinction()); }

  // Throws std::invalid_argument naming what is wrong: coefficients negative or not finite, a
  // channel with no extinction at all, g outside (-1, 1), eta not positive.
  void validate() const {
    for (int c = 0; c < 3; ++c) {
      if (!(sigmaS[c] >= 0) || !(sigmaA[c] >= 0) || !std::isfinite(sigmaS[c]) || !std::isfinite(sigmaA[c]))
        throw std::invalid_argument("scattering medium: coefficients must be finite and >= 0");
      if (!(sigmaS[c] + sigmaA[c] > 0))
        throw std::invalid_argument("scattering medium: channel " + std::to_string(c) +
                                    " has sigma_s + sigma_a = 0 (no interaction: no subsurface profile)");
    }
    if (!(g > -1 && g < 1)) throw std::invalid_argument("scattering medium: g must be in (-1, 1)");
    if (!(eta > 0) || !std::isfinite(eta))
      throw std::invalid_argument("scattering medium: eta must be positive");
  }

 private:
  static Rgb ratio(const Rgb& a, const Rgb& b) {
    Rgb out{0.0};
    for (int c = 0; c < 3; ++c) out[c] = b[c] > 0 ? a[c] / b[c] : 0.0;
    return out;
  }
};

}  // namespace scatterlab
