// The index of refraction of the dielectric models (smooth_dielectric.h, thin_dielectric.h,
// rough_dielectric.h, rough_plastic.h): the values it may take and its parameter
// (materials/registry/parameter_spec.h).
#pragma once

#include <string>

#include "materials/registry/parameter_spec.h"

namespace scatterlab {

// (1, 4]: every transparent dielectric of the optical range (water 1.33, glass 1.5, diamond
// 2.42, rutile 2.9, up to germanium's ~4 in the near infrared). 1 is excluded: an
// index-matched interface is no surface at all (the smooth and thin models would pass
// everything straight through with R = 0) and leaves rough refraction undefined (no
// generalised half vector for wo = -wi). A denser medium above (an air bubble in water) is
// the same interface with the normal flipped: eta = 1.33 with the normal into the air.
inline const ValueRange DielectricIndexRange{1.0, 4.0, true, false};

// The rough dielectric's refracted lobe is about (1 - 1/eta) times as wide as the facet
// distribution: at alpha 0.001 and eta 1.005 it is ~1e-5 rad wide at normal incidence, 5e-11
// in cos(theta) at the pole, finer than the kit's sample probes (2^-32) can locate, and the
// kit fails there; from 1.01 up it passes on grids from 4 x 8 to 64 x 128 cells. A material
// the kit cannot check is not offered: eta >= 1.02, with margin (only aerogels are below).
inline const ValueRange RoughDielectricIndexRange = ValueRange::closed(1.02, 4.0);

// "eta", default 1.5, in `range`.
ParameterSpec dielectricIndexParameter(const ValueRange& range, std::string description);

}  // namespace scatterlab
