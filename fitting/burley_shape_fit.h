// Christensen & Burley 2015's shape factor s fitted to the half-space random walk: the
// searchlight configuration of their first fit (normal incidence, mean free path l = 1,
// g = 0, index-matched), in which s = 1.85 - A + 7 |A - 0.8|^3 was fitted to Monte Carlo
// profiles. For a total reflectance A, the walk's medium is the single-scattering albedo c
// with 1 - H(1) sqrt(1 - c) = A (Chandrasekhar's H: searchlightAlbedoForReflectance), so the
// walk's profile integrates to A and only the shape is left to fit: R(r) of Burley's
// normalised diffusion with that A and d = l / s.
//
// The metric. The memo fits its profiles to the Monte Carlo references as curves r R(r) (the
// quantity it plots, finite at r = 0) and reports the relative error of the fits; it does not
// state the norm. We use least squares of r R(r) over radius,
//   E(s) = integral_0^rmax [r (R_walk(r) - R(r; s))]^2 dr,
// on annuli of the walk's tally: residual_k = sqrt(r_k+1 - r_k) r_mid (Rbar_walk - Rbar(s)),
// with Burley's annulus averages exact from its CDF (R itself diverges at r = 0). The fitted
// and the published s are then both scored by the r-weighted relative error of their profiles
// against the walk (annulus_profile.h).
#pragma once

#include <cstdint>

#include "fitting/radial_profile_fit.h"
#include "materials/bssrdf/burley.h"
#include "materials/bssrdf/half_space_walk.h"

namespace scatterlab::fitting {

// The fitter's functor: Burley's cumulative reflectance with A and l held, s the parameter.
struct BurleyShapeProfile {
  static constexpr int ParameterCount = 1;  // s
  double albedo = 0.5;                      // A
  double length = 1.0;                      // l, mm: d = l / s
  template <typename T> T cumulative(const T* p, double r) const {
    return burleyCumulative(T(albedo), T(length) / p[0], T(r));
  }
};

// The walk that s(A) is fitted to: single-scattering albedo c(A), sigma_t = 1, g = 0, eta = 1,
// normal incidence, annuli of width `annulusWidth` (mean free paths) out to three times the
// radius that holds 99.9% of the published fit's profile (the walk's tail is longer than
// Burley's; what leaves beyond counts in the total only). A in (0, 1).
HalfSpaceWalkSettings burleyShapeWalkSettings(double albedo, uint64_t paths, uint64_t seed, double annulusWidth = 0.02);

struct BurleyShapeFit {
  double albedo = 0.0;            // A: the profile's total, the walk's exact total reflectance
  double walkAlbedo = 0.0;        // c, the walk's single-scattering albedo
  double walkReflectance = 0.0, walkStdError = 0.0;  // the walk's total (should equal A)
  double shapeFactor = 0.0;       // fitted s
  double shapeStdError = 0.0;     // standard deviation of the fitted s from the walk's noise
  double publishedShapeFactor = 0.0;  // 1.85 - A + 7 |A - 0.8|^3
  double fitError = 0.0;          // r-weighted relative error of the fitted profile against the walk
  double publishedError = 0.0;    // the same for the published s
  double errorNoiseFloor = 0.0;   // what the walk's noise alone adds to either (radialNoiseFloor)
  RadialFitResult fit;
};

// The errors are measured on this many log-spaced groups of the walk's annuli.
inline constexpr int ErrorAnnuli = 32;

// Fits s to a walk run with burleyShapeWalkSettings(albedo, ...) (any increasing annuli work:
// the residuals carry sqrt of their widths). Throws std::invalid_argument when the walk has no
// annuli.
BurleyShapeFit fitBurleyShapeFactor(const HalfSpaceWalkResult& walk, double albedo);

}  // namespace scatterlab::fitting
