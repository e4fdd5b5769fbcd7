// The Generalized-Trowbridge-Reitz distribution with gamma = 1 ("GTR1"), Burley 2012,
// "Physically-Based Shading at Disney" (SIGGRAPH course notes), section 5.4 eq. 4 and
// appendix B: the long-tailed normal distribution of the Disney BRDF's clearcoat lobe,
//   D(m) = (alpha^2 - 1) / (pi ln(alpha^2) (1 + (alpha^2 - 1) cos^2 theta_m)),  0 < alpha < 1,
// normalised so that integral D(m) cos theta_m dm = 1 (at alpha = 1 it is the limit 1/pi).
// Sampling m with density D(m) cos theta_m (appendix B): phi = 2 pi u1 and
//   cos^2 theta_m = (1 - alpha^(2 (1 - u0))) / (1 - alpha^2),
// the inverse of the CDF of t = cos^2 theta_m, P(cos^2 >= t) = 1 - ln(1 + (alpha^2 - 1) t) / ln(alpha^2).
// A pbrt-v4 style triplet (sampleClassic / pdfClassic / invertClassic, the names of
// microfacet.h, so that half_vector.h's classic reflection helpers take it as they are).
// GTR1 has no closed-form Smith masking; the Disney clearcoat uses GGX's with alpha 0.25.
#pragma once

#include <concepts>

#include "materials/bsdf/microfacet.h"

namespace scatterlab {

template <typename T> class Gtr1Distribution {
 public:
  // alpha in (0, 1]; the Disney clearcoat uses alpha in [0.001, 0.1].
  explicit Gtr1Distribution(T alpha) : alpha_(alpha) {}

  const T& alpha() const { return alpha_; }

  // Written with 1 + (alpha^2 - 1) cos^2 = sin^2 + alpha^2 cos^2 = m.x^2 + m.y^2 + alpha^2 m.z^2
  // (no cancellation near the pole of a sharp lobe), and (alpha^2 - 1) / ln(alpha^2) by its
  // series near alpha = 1, where both vanish (value and derivative stay finite there).
  T D(const Vec3<T>& m) const {
    if (!(m.z > T(0))) return T(0);
    const T alpha2 = alpha_ * alpha_;
    const T t = m.x * m.x + m.y * m.y + alpha2 * m.z * m.z;
    return normalization(alpha2) / (T(Pi) * t);
  }

  // Density of sampleClassic per solid angle of m.
  double pdfClassic(const Vec3d& m) const requires std::same_as<T, double> {
    return m.z > 0 ? D(m) * m.z : 0.0;
  }

  // With L = ln(alpha^2): cos^2 = expm1((1 - u0) L) / expm1(L) and, without cancellation for
  // the normals near the pole, sin^2 = exp((1 - u0) L) expm1(u0 L) / expm1(L).
  Vec3d sampleClassic(const Vec2d& u) const requires std::same_as<T, double> {
    const double logAlpha2 = std::log(alpha_ * alpha_);
    double cos2, sin2;
    if (logAlpha2 == 0.0) {  // alpha = 1: D = 1/pi, cos^2 uniform
      cos2 = 1.0 - u.x;
      sin2 = u.x;
    } else {
      const double denominator = std::expm1(logAlpha2);
      cos2 = std::expm1((1.0 - u.x) * logAlpha2) / denominator;
      sin2 = std::exp((1.0 - u.x) * logAlpha2) * std::expm1(u.x * logAlpha2) / denominator;
    }
    const double sinTheta = safeSqrt(sin2), cosTheta = safeSqrt(cos2);
    const double phi = 2.0 * Pi * u.y;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
  }

  // u0 = 1 - ln(1 + (alpha^2 - 1) cos^2) / L = -ln(1 + sin^2 (alpha^-2 - 1)) / L, the second
  // form exact for the normals near the pole.
  Vec2d invertClassic(const Vec3d& m) const requires std::same_as<T, double> {
    const double sin2 = m.x * m.x + m.y * m.y;
    const double logAlpha2 = std::log(alpha_ * alpha_);
    const double u0 = logAlpha2 == 0.0 ? sin2 : -std::log1p(sin2 * std::expm1(-logAlpha2)) / logAlpha2;
    return {std::clamp(u0, 0.0, 1.0), azimuthToUnit(m.y, m.x)};
  }

 private:
  // (alpha^2 - 1) / ln(alpha^2); with x = alpha^2 - 1, x / ln(1 + x) = 1 + x/2 - x^2/12 + x^3/24 - ...
  static T normalization(const T& alpha2) {
    using std::abs;
    using std::log;
    const T x = alpha2 - T(1);
    if (abs(x) < T(1e-4)) return T(1) + x * (T(0.5) - x * (T(1.0 / 12.0) - x * T(1.0 / 24.0)));
    return x / log(alpha2);
  }

  T alpha_;
};

}  // namespace scatterlab
