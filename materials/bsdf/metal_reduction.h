// From measured spectra of a metal's complex index (n(lambda), k(lambda)) to one (eta, k) per
// linear-RGB channel; the method that produced the table in metals.cpp (data/ior/README.md):
//  1. R(lambda): normal-incidence reflectance ((n-1)^2 + k^2) / ((n+1)^2 + k^2).
//  2. RGB reflectance: linear Rec.709 of the CIE XYZ of R under the equal-energy illuminant,
//     each channel divided by that of a perfect reflector (R = 1 gives (1, 1, 1)).
//  3. eta_c: mean of n(lambda) weighted by max(0, channel c's colour matching function).
//  4. k_c: the closed-form k for which (eta_c, k_c) has normal-incidence reflectance RGB_c
//     exactly; where no k >= 0 can (RGB_c below the reflectance of eta_c with k = 0), k_c = 0
//     and eta_c moves (on its side of 1) to the dielectric index with that reflectance.
// Integrals use the trapezoid rule on integer wavelengths from 380 to 780 nm (clipped to the
// range both spectra cover), spectra linearly interpolated between their samples.
#pragma once

#include <filesystem>
#include <istream>
#include <vector>

#include "materials/bsdf/metals.h"

namespace scatterlab {

// A sampled spectrum: wavelengths in nm, strictly increasing, one value each.
struct Spectrum {
  std::vector<double> wavelengths;
  std::vector<double> values;

  // Linear interpolation between samples; outside the sampled range, the end values.
  double at(double lambda) const;
};

// .spd text: one "wavelength-nm value" pair per line; '#' starts a comment, blank lines are
// skipped. Throws std::runtime_error naming the source and line on malformed input, fewer than
// two samples, or wavelengths that do not increase.
Spectrum parseSpd(std::istream& in, const std::string& sourceName);
Spectrum readSpd(const std::filesystem::path& path);

// Step 2 above: the RGB normal-incidence reflectance of the spectra.
Rgb normalIncidenceReflectanceRgb(const Spectrum& eta, const Spectrum& k);

// Step 2's colour for any reflectance spectrum (a measured BRDF's spectral samples,
// rgl_brdf.h): RGB of R(lambda) with R = 1 giving (1, 1, 1), over the visible wavelengths the
// spectrum covers. Linear in the spectrum's values. Throws std::runtime_error when the
// spectrum does not overlap 380-780 nm.
Rgb reflectanceRgb(const Spectrum& reflectance);

// Step 4 above for one channel: the (eta, k) with normal-incidence reflectance `reflectance`,
// keeping `eta` when some k >= 0 achieves it. Throws std::domain_error unless 0 <= R < 1.
struct ComplexIndex {
  double eta, k;
};
ComplexIndex indexWithNormalReflectance(double eta, double reflectance);

// Steps 1-4. `name` is stored as given (pass a string that outlives the result).
MetalIor reduceMetalSpectra(const char* name, const Spectrum& eta, const Spectrum& k);

}  // namespace scatterlab
