// A BSDF in its plane of incidence, the lobe plots of the report (as in Disney's BRDF
// Explorer): wi at polar angle theta_i and azimuth phi, wo swept through the plane that holds
// wi and the normal, at signed angle t from the normal: t > 0 on the far side from wi (where
// the mirror direction t = theta_i lies), t < 0 back toward wi, |t| > 90 below the surface
// (transmission). wo(t) = (sin t cos phi', sin t sin phi', cos t) with phi' = phi + pi.
#pragma once

#include <vector>

#include "materials/bsdf/bsdf.h"

namespace scatterlab {

struct LobeCurve {
  double thetaInDeg = 0;
  std::vector<double> thetaOutDeg;  // t, signed (see above)
  std::vector<Rgb> value;           // f(wi, wo(t)), sr^-1, without the cosine
};

// `directions` values of t evenly over [-90, 90], or over [-180, 180] for models with
// transmission (both ends included).
LobeCurve lobeInPlaneOfIncidence(const BsdfModel& model, double thetaInDeg, double phiDeg, int directions);

// Rec. 709 luminance of linear RGB (the single number a lobe plot shows).
double rec709Luminance(const Rgb& c);

}  // namespace scatterlab
