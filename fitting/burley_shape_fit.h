// Christensen & Burley 2015's shape factor s fitted to the half-space random walk: the
// searchlight configuration of their first fit (normal incidence, mean free path l = 1,
// g = 0, index-matched), in which s = 1.85 - A + 7 |A - 0.8|^3 was fitted to Monte Carlo
// profiles. For a total reflectance A, the walk's medium is the single-scattering albedo c
// with 1 - H(1) sqrt(1 - c) = A (Chandrasekhar's H: searchlightAlbedoForReflectance), so the
// walk's profile integrates to A.
//
// The metric. The memo fits its profiles to the Monte Carlo references as curves r R(r) (the
// quantity it plots, finite at r = 0) and reports the relative error of the fits; it states
// neither the norm nor whether the curve's height was held. We use least squares of r R(r)
// over radius,
//   E = integral_0^rmax [r (R_walk(r) - R(r))]^2 dr,
// on annuli of the walk's tally: residual_k = sqrt(r_k+1 - r_k) r_mid (Rbar_walk - Rbar), with
// Burley's annulus averages exact from its CDF (R itself diverges at r = 0), and fit s twice:
//   shape       the curve P (e^(-s r) + e^(-s r / 3)) s / (8 pi r) with its power P free as
//               well: the shape of the profile where its light comes out. This reproduces the
//               published s(A) (README, "Burley's shape factor, fitted"); with P held at A
//               the fit cannot.
//   normalised  P held at A, the profile a renderer uses. Above A ~ 0.85 the walk's diffusive
//               tail (e^(-sqrt(3 (1 - c)) r)) carries power that Burley's e^(-s r / 3) cannot
//               follow, and this s widens the whole shape to carry it.
// Each s's profile at power A (as rendered) and the published one are then scored by the
// r-weighted relative error against the walk (annulus_profile.h).
#pragma once

#include <cstdint>

#include "fitting/radial_profile_fit.h"
#include "materials/bssrdf/burley.h"
#include "materials/bssrdf/half_space_walk.h"

namespace scatterlab::fitting {

// The normalised fit's functor: Burley's cumulative reflectance with A and l held, s the
// parameter.
struct BurleyShapeProfile {
  static constexpr int ParameterCount = 1;  // s
  double albedo = 0.5;                      // A
  double length = 1.0;                      // l, mm: d = l / s
  template <typename T> T cumulative(const T* p, double r) const {
    return burleyCumulative(T(albedo), T(length) / p[0], T(r));
  }
};

// The shape fit's functor: the curve's power P and s, l held.
struct BurleyPowerAndShapeProfile {
  static constexpr int ParameterCount = 2;  // P, s
  double length = 1.0;                      // l, mm: d = l / s
  template <typename T> T cumulative(const T* p, double r) const {
    return burleyCumulative(p[0], T(length) / p[1], T(r));
  }
};

// The walk that s(A) is fitted to: single-scattering albedo c(A), sigma_t = 1, g = 0, eta = 1,
// normal incidence, annuli of width `annulusWidth` (mean free paths) out to three times the
// radius that holds 99.9% of the published fit's profile (the walk's tail is longer than
// Burley's; what leaves beyond counts in the total only). A in (0, 1).
HalfSpaceWalkSettings burleyShapeWalkSettings(double albedo, uint64_t paths, uint64_t seed,
                                              double annulusWidth = 0.02);

struct BurleyShapeFit {
  double albedo = 0.0;                               // A: the walk's exact total reflectance
  double walkAlbedo = 0.0;                           // c, the walk's single-scattering albedo
  double walkReflectance = 0.0, walkStdError = 0.0;  // the walk's total (should equal A)
  double publishedShapeFactor = 0.0;                 // 1.85 - A + 7 |A - 0.8|^3

  // The shape fit (power free) and the normalised fit (power A). Standard deviations are those
  // of the walk's noise (sandwich estimate over its independent annuli).
  double shapeFactor = 0.0, shapeStdError = 0.0;
  double power = 0.0, powerStdError = 0.0;  // P of the shape fit
  double normalisedShapeFactor = 0.0, normalisedStdError = 0.0;
  RadialFitResult shapeFit, normalisedFit;

  // r-weighted relative error against the walk of Burley's profile at power A with each s.
  double shapeError = 0.0, normalisedError = 0.0, publishedError = 0.0;
  double errorNoiseFloor = 0.0;  // what the walk's noise alone adds to any of them (radialNoiseFloor)
};

// The errors are measured on this many log-spaced groups of the walk's annuli.
inline constexpr int ErrorAnnuli = 32;

// Fits s to a walk run with burleyShapeWalkSettings(albedo, ...) (any increasing annuli work:
// the residuals carry sqrt of their widths). Throws std::invalid_argument when the walk has no
// annuli.
BurleyShapeFit fitBurleyShapeFactor(const HalfSpaceWalkResult& walk, double albedo);

}  // namespace scatterlab::fitting
