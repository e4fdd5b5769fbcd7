// Probe sampling of exit points (King, Kulla, Conty & Fajardo 2013, "BSSRDF Importance
// Sampling", SIGGRAPH Talks; pbrt-v3 SeparableBSSRDF::Sample_Sp and Pdf_Sp), with its exact
// density per unit area of the surface found.
//
// From the entry point xi with frame (s, t, n): choose a probe axis a (n with probability 0.5,
// s and t 0.25 each) and a colour channel c; draw r from c's radius distribution truncated at
// r_max(c) (its 0.999 quantile) and phi uniformly; the probe is the chord of the sphere of
// radius r_max(c) around xi that passes, parallel to a, through the point at (r, phi) of the
// disk perpendicular to a. A surface point xo that the chord crosses was found with density
// (per unit area at xo, normal no)
//   pdf(xo) = sum_axes P(a) |no . a| sum_channels P(c) p_c(r_a) / (2 pi r_a) [|xo - xi| < r_max(c)],
// r_a = |xo - xi| projected onto the plane perpendicular to a, p_c the truncated radius density
// (p / 0.999): each axis and channel could have produced xo, through its own projected radius,
// and only while the chord still reaches xo (the bracket: pbrt-v3's Pdf_Sp omits it, which is
// exact only where every point within r_max of xi lies within r_max of the disk's plane).
// A radial shortcut p_c(|xo - xi|) / (2 pi |xo - xi|) is not this density: the kit rejects it.
// If the chord crosses the surface k times and one crossing is chosen uniformly, the density of
// the chosen point is pdf / k (the renderer's business).
#pragma once

#include <array>
#include <optional>

#include "materials/bssrdf/bssrdf.h"
#include "materials/core/frame.h"

namespace scatterlab {

struct ProbeSampling {
  std::array<double, 3> axisProbability{0.5, 0.25, 0.25};  // n, s, t
  std::array<double, 3> channelProbability{1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
  double truncation = 0.999;  // radius CDF at r_max
};

// Equal channel probabilities over the channels that reflect anything (Rd > 0; a channel that
// reflects nothing has no radius distribution).
ProbeSampling defaultProbeSampling(const RadialProfile& profile);

struct ProbeSegment {
  Vec3d start, end;  // the chord, start + t (end - start) for t in [0, 1]
  int axis = 0;      // 0: n, 1: s, 2: t
  int channel = 0;
  double radius = 0.0;
};

class ProbeSampler {
 public:
  // `profile` must outlive the sampler; every channel with positive probability must have
  // Rd > 0. Throws std::invalid_argument on probabilities that are negative or do not sum to 1.
  explicit ProbeSampler(const RadialProfile& profile);
  ProbeSampler(const RadialProfile& profile, const ProbeSampling& sampling);

  const ProbeSampling& sampling() const { return sampling_; }
  double maxRadius(int channel) const { return maxRadius_[channel]; }
  double largestRadius() const;

  // uChoice picks the axis and then the channel (each remapped to [0, 1) in turn); u.x the
  // radius, u.y the angle.
  ProbeSegment sample(const Framed& frame, const Vec3d& origin, double uChoice, const Vec2d& u) const;
  // The density per unit area of finding xo (surface normal normalAtExit) with probes from
  // (frame, origin), above.
  double pdf(const Framed& frame, const Vec3d& origin, const Vec3d& xo, const Vec3d& normalAtExit) const;
  // The truncated radius density per unit area of the disk, p_c(r) / (2 pi r), 0 beyond r_max.
  double diskDensity(int channel, double r) const;

 private:
  const RadialProfile* profile_;
  ProbeSampling sampling_;
  std::array<double, 3> maxRadius_{};
};

}  // namespace scatterlab
