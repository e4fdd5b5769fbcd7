// CIE 1931 2-degree colour matching functions and the conversion from XYZ to linear RGB with
// Rec.709 primaries (scatterlab's colour space, docs/design.md, "Units and colour"): what turns a spectrum
// into RGB.
#pragma once

#include "materials/core/math.h"

namespace scatterlab {

// A Gaussian whose standard deviation differs on the two sides of its mean.
inline double piecewiseGaussian(double lambda, double mean, double sigmaBelow, double sigmaAbove) {
  const double t = (lambda - mean) / (lambda < mean ? sigmaBelow : sigmaAbove);
  return std::exp(-0.5 * t * t);
}

// x-bar, y-bar, z-bar at wavelength lambda (nm): the multi-lobe piecewise-Gaussian fit of
// Wyman, Sloan & Shirley 2013, "Simple Analytic Approximations to the CIE XYZ Color Matching
// Functions" (JCGT 2(2)), eq. 2. Smooth and defined at any
// wavelength, so spectra can be integrated on their own sampling.
inline Vec3d cieXyzMatching(double lambda) {
  const double x = 1.056 * piecewiseGaussian(lambda, 599.8, 37.9, 31.0) +
                   0.362 * piecewiseGaussian(lambda, 442.0, 16.0, 26.7) -
                   0.065 * piecewiseGaussian(lambda, 501.1, 20.4, 26.2);
  const double y = 0.821 * piecewiseGaussian(lambda, 568.8, 46.9, 40.5) +
                   0.286 * piecewiseGaussian(lambda, 530.9, 16.3, 31.1);
  const double z = 1.217 * piecewiseGaussian(lambda, 437.0, 11.8, 36.0) +
                   0.681 * piecewiseGaussian(lambda, 459.0, 26.0, 13.8);
  return {x, y, z};
}

// XYZ -> linear RGB with Rec.709 primaries and D65 white (ITU-R BT.709-6: primaries
// (0.64, 0.33), (0.30, 0.60), (0.15, 0.06), white (0.3127, 0.3290)); the inverse of the
// primaries' XYZ matrix scaled so that D65 maps to (1, 1, 1), computed exactly in rationals.
// Rows are R, G, B.
inline constexpr double XyzToRec709[3][3] = {
    {3.2409699419045213, -1.5373831775700935, -0.49861076029300327},
    {-0.96924363628087984, 1.8759675015077206, 0.041555057407175612},
    {0.055630079696993608, -0.20397695888897657, 1.0569715142428786},
};

inline Rgb xyzToLinearRec709(const Vec3d& xyz) {
  Rgb rgb;
  for (int row = 0; row < 3; ++row)
    rgb[row] = XyzToRec709[row][0] * xyz.x + XyzToRec709[row][1] * xyz.y + XyzToRec709[row][2] * xyz.z;
  return rgb;
}

// The colour matching functions of the linear Rec.709 channels (they have negative lobes).
inline Rgb rec709Matching(double lambda) { return xyzToLinearRec709(cieXyzMatching(lambda)); }

}  // namespace scatterlab
