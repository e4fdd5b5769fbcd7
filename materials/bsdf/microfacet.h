// Microfacet normal distributions with Smith masking-shadowing: GGX (Trowbridge-Reitz) and
// Beckmann, anisotropic, in the local frame (alphaX along the tangent x, alphaY along y).
//
// Both classes have the same interface. The evaluation functions are templated on the scalar
// T (double for rendering, ceres::Jet for fitting); the samplers exist for T = double only and
// come as pbrt-v4 style triplets (sample / pdf / invert), so that invert(sample(u)) == u can
// be tested and the chi-square kit can compare sample() with pdf().
//
// Smith quantities are computed through the projected area of the back-facing microfacets,
// B(w) = |cos theta| Lambda(w) = integral of max(0, -w.m) D(m) dm (Heitz 2014, "Understanding
// the Masking-Shadowing Function in Microfacet-Based BRDFs", JCGT 3(2)):
// unlike Lambda, B is finite on the horizon, so G1, G2 and the visible-normal density are
// evaluated without dividing by cos theta and stay finite (value and derivative) at grazing.
#pragma once

#include <concepts>
#include <limits>
#include <type_traits>
#include <utility>

#include "materials/bsdf/microfacet_type.h"
#include "materials/core/special_functions.h"
#include "materials/core/spherical.h"

namespace scatterlab {

// ---- What GGX and Beckmann share: Smith's masking from the back-facing projected area ----
//
// Derived provides D(m) and backfacingArea(w) = |cos theta| Lambda(w).
template <typename Derived, typename T> class SmithMicrofacet {
 public:
  SmithMicrofacet(T alphaX, T alphaY) : alphaX_(alphaX), alphaY_(alphaY) {}

  const T& alphaX() const { return alphaX_; }
  const T& alphaY() const { return alphaY_; }
  bool isotropic() const { return alphaX_ == alphaY_; }

  // Smith Lambda (Heitz 2014); 0 at the pole, infinite exactly on the horizon,
  // where the microsurface masks everything.
  T lambda(const Vec3<T>& w) const {
    using std::abs;
    const T cosTheta = abs(w.z);
    if (cosTheta == T(0)) return T(std::numeric_limits<double>::infinity());
    return derived().backfacingArea(w) / cosTheta;
  }

  // Projected area of the microsurface seen from w, per unit macro-surface area:
  // integral of max(0, w.m) D(m) dm = |cos theta| (1 + Lambda(w)) (Heitz 2014).
  T projectedArea(const Vec3<T>& w) const {
    using std::abs;
    return abs(w.z) + derived().backfacingArea(w);
  }

  // Smith masking, 1 / (1 + Lambda(w)) (Heitz 2014), written as cos / projected area.
  T G1(const Vec3<T>& w) const {
    using std::abs;
    const T area = projectedArea(w);
    return area > T(0) ? abs(w.z) / area : T(0);
  }

  // Height-correlated masking-shadowing for reflection, 1 / (1 + Lambda(wi) + Lambda(wo))
  // (Heitz 2014 eq. 99), multiplied through by cos_i cos_o. The denominator is written
  // symmetrically so that G2(wi, wo) and G2(wo, wi) round identically.
  T G2(const Vec3<T>& wi, const Vec3<T>& wo) const {
    using std::abs;
    const T cosI = abs(wi.z), cosO = abs(wo.z);
    const T denominator =
        cosI * cosO + (cosO * derived().backfacingArea(wi) + cosI * derived().backfacingArea(wo));
    return denominator > T(0) ? cosI * cosO / denominator : T(0);
  }

  // Distribution of normals visible from w (w.z >= 0), G1(w) max(0, w.m) D(m) / cos theta
  // (Heitz 2014 eq. 38); integrates to 1 over the hemisphere of m.
  T visibleD(const Vec3<T>& w, const Vec3<T>& m) const {
    if (w.z < T(0)) return T(0);
    const T cosWM = glm::dot(w, m);
    if (!(cosWM > T(0))) return T(0);
    const T area = projectedArea(w);
    return area > T(0) ? cosWM * derived().D(m) / area : T(0);
  }

  double pdfVisible(const Vec3d& w, const Vec3d& m) const requires std::same_as<T, double> {
    return visibleD(w, m);
  }
  // Density of sampleClassic per solid angle of m: D(m) cos theta_m, normalised by definition
  // of D (Heitz 2014).
  double pdfClassic(const Vec3d& m) const requires std::same_as<T, double> {
    return m.z > 0 ? derived().D(m) * m.z : 0.0;
  }

 private:
  const Derived& derived() const { return static_cast<const Derived&>(*this); }

  T alphaX_, alphaY_;
};

// The azimuth of a point (x, y) mapped to [0, 1), the inverse of phi = 2 pi u.
inline double azimuthToUnit(double y, double x) {
  double phi = std::atan2(y, x);
  if (phi < 0) phi += 2.0 * Pi;
  const double u = phi * Inv2Pi;
  return u < 1.0 ? u : 0.0;
}

// ---- GGX / Trowbridge-Reitz ----
template <typename T> class GgxDistribution : public SmithMicrofacet<GgxDistribution<T>, T> {
  using Base = SmithMicrofacet<GgxDistribution<T>, T>;

 public:
  GgxDistribution(T alphaX, T alphaY) : Base(alphaX, alphaY) {}
  using Base::alphaX;
  using Base::alphaY;

  // D(m) = 1 / (pi ax ay cos^4 (1 + tan^2 (cos^2 phi / ax^2 + sin^2 phi / ay^2))^2)
  // (Walter et al. 2007 eq. 33, anisotropic form Heitz 2014); multiplying cos^4 into
  // the bracket gives the form below, which needs no tan and no division by cos theta_m.
  T D(const Vec3<T>& m) const {
    if (!(m.z > T(0))) return T(0);
    const T e = sqr(m.x / alphaX()) + sqr(m.y / alphaY()) + sqr(m.z);
    return T(1) / (T(Pi) * alphaX() * alphaY() * e * e);
  }

  // |cos| Lambda with Lambda = (sqrt(1 + alpha^2 tan^2 theta) - 1) / 2 (Heitz 2014),
  // alpha^2 tan^2 = (ax^2 x^2 + ay^2 y^2) / z^2; rationalised so that there is no
  // cancellation near the pole and no division by z at the horizon.
  T backfacingArea(const Vec3<T>& w) const {
    using std::abs;
    using std::sqrt;
    const T s2 = sqr(alphaX() * w.x) + sqr(alphaY() * w.y);
    if (!(s2 > T(0))) return T(0);
    const T cosTheta = abs(w.z);
    return s2 / (T(2) * (sqrt(cosTheta * cosTheta + s2) + cosTheta));
  }

  // Heitz 2018, "Sampling the GGX Distribution of Visible Normals" (JCGT 7(4)):
  // stretch w to the alpha = 1 configuration, where the visible normals are a hemisphere seen
  // from w; sample its projection, a disk whose part hidden by the horizon is folded onto the
  // visible half by the t2 warp; lift to the hemisphere and unstretch.
  Vec3d sampleVisible(const Vec3d& w, const Vec2d& u) const requires std::same_as<T, double> {
    const Vec3d wh = stretched(w);
    const auto [t1Axis, t2Axis] = diskBasis(wh);
    const double r = std::sqrt(u.x);
    const double phi = 2.0 * Pi * u.y;
    const double t1 = r * std::cos(phi);
    const double s = 0.5 * (1.0 + wh.z);
    const double t2 = (1.0 - s) * safeSqrt(1.0 - t1 * t1) + s * (r * std::sin(phi));
    const Vec3d nh = t1 * t1Axis + t2 * t2Axis + safeSqrt(1.0 - t1 * t1 - t2 * t2) * wh;
    return glm::normalize(Vec3d(alphaX() * nh.x, alphaY() * nh.y, std::max(0.0, nh.z)));
  }

  // The steps of sampleVisible undone: restretch m onto the hemisphere, project on the disk,
  // unfold the t2 warp, and read the polar coordinates.
  Vec2d invertVisible(const Vec3d& w, const Vec3d& m) const requires std::same_as<T, double> {
    const Vec3d wh = stretched(w);
    const auto [t1Axis, t2Axis] = diskBasis(wh);
    const Vec3d nh = glm::normalize(Vec3d(m.x / alphaX(), m.y / alphaY(), m.z));
    const double t1 = glm::dot(nh, t1Axis);
    const double s = 0.5 * (1.0 + wh.z);
    const double t2 = (glm::dot(nh, t2Axis) - (1.0 - s) * safeSqrt(1.0 - t1 * t1)) / s;
    return {std::clamp(t1 * t1 + t2 * t2, 0.0, 1.0), azimuthToUnit(t2, t1)};
  }

  // m with density D(m) cos theta_m. In slope space the alpha = 1 GGX is the radially
  // symmetric P22 = 1 / (pi (1 + r^2)^2) with CDF r^2 / (1 + r^2) (Walter et al. 2007
  // eq. 35-36); so tan^2 theta = u / (1 - u), written without the division so u -> 1 gives the
  // horizon instead of an overflow, then stretched by (ax, ay).
  Vec3d sampleClassic(const Vec2d& u) const requires std::same_as<T, double> {
    const double r = std::sqrt(u.x);
    const double phi = 2.0 * Pi * u.y;
    return glm::normalize(
        Vec3d(alphaX() * r * std::cos(phi), alphaY() * r * std::sin(phi), safeSqrt(1.0 - u.x)));
  }

  Vec2d invertClassic(const Vec3d& m) const requires std::same_as<T, double> {
    const double qx = m.x / alphaX(), qy = m.y / alphaY();
    const double q2 = qx * qx + qy * qy;
    const double total = q2 + m.z * m.z;
    return {total > 0 ? q2 / total : 0.0, azimuthToUnit(qy, qx)};
  }

 private:
  Vec3d stretched(const Vec3d& w) const requires std::same_as<T, double> {
    return glm::normalize(Vec3d(alphaX() * w.x, alphaY() * w.y, w.z));
  }
  // An orthonormal basis of the plane perpendicular to wh, t1 horizontal (Heitz 2018).
  static std::pair<Vec3d, Vec3d> diskBasis(const Vec3d& wh) {
    const double lengthSquared = wh.x * wh.x + wh.y * wh.y;
    const Vec3d t1 = lengthSquared > 0 ? Vec3d(-wh.y, wh.x, 0.0) / std::sqrt(lengthSquared) : Vec3d(1, 0, 0);
    return {t1, glm::cross(wh, t1)};
  }
};

// ---- Beckmann ----

// The marginal of the x slope of the visible normals of the alpha = 1 Beckmann distribution,
// seen from theta in the xz-plane (Heitz & d'Eon 2014, "Importance Sampling Microfacet-Based
// BSDFs using the Distribution of Visible Normals"): density proportional to
// exp(-x^2) (cos theta - x sin theta) on x < cot theta. Its unnormalised CDF is
//   F(x) = cos theta (sqrt(pi) / 2) erfc(-x) + sin theta exp(-x^2) / 2,
// a sum of positive terms, so F keeps full relative precision in both tails.
class BeckmannVisibleSlopeX {
 public:
  BeckmannVisibleSlopeX(double cosTheta, double sinTheta)
      : cosTheta_(cosTheta),
        sinTheta_(sinTheta),
        upper_(std::min(sinTheta > 0 ? cosTheta / sinTheta : Infinity, SlopeLimit)),
        total_(unnormalizedCdf(upper_)) {}

  // Beyond |x| = 26 the density is below exp(-676) relative to its peak, far under the
  // resolution of a double u: the slope is solved on [-26, min(cot theta, 26)].
  static constexpr double SlopeLimit = 26.0;

  double cdf(double x) const { return x >= upper_ ? 1.0 : std::clamp(unnormalizedCdf(x) / total_, 0.0, 1.0); }

  // Solves cdf(x) = u by Newton's method safeguarded by bisection on the bracket: exact up to
  // round-off (steps below 1e-13), with no fitted approximation.
  double invert(double u) const {
    const double target = u * total_;
    double lo = -SlopeLimit, hi = upper_;
    if (!(target > unnormalizedCdf(lo))) return lo;
    if (!(target < total_)) return hi;
    // Start from the approximate normal-incidence quantile, erf^-1(2u - 1); the safeguards
    // take over where the incident angle makes it a poor guess.
    double x = std::clamp(erfinvInitialGuess(2.0 * u - 1.0, 4.0 * u * (1.0 - u)), lo, hi);
    for (int iteration = 0; iteration < 200; ++iteration) {
      const double excess = unnormalizedCdf(x) - target;
      if (excess > 0)
        hi = x;
      else
        lo = x;
      const double density = unnormalizedDensity(x);
      const double tolerance = 1e-14 * (1.0 + std::abs(x));
      if (density > 0) {
        const double newton = x - excess / density;
        // Tested before the bracket: a converged step may land on the bracket's end.
        if (std::abs(newton - x) <= tolerance) return newton;
        x = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
      } else {
        x = 0.5 * (lo + hi);
      }
      if (hi - lo <= tolerance) break;
    }
    return x;
  }

 private:
  static constexpr double Infinity = std::numeric_limits<double>::infinity();

  double unnormalizedCdf(double x) const {
    return cosTheta_ * (0.5 * SqrtPi) * std::erfc(-x) + sinTheta_ * 0.5 * std::exp(-x * x);
  }
  double unnormalizedDensity(double x) const {
    return x < upper_ ? std::exp(-x * x) * (cosTheta_ - x * sinTheta_) : 0.0;
  }

  double cosTheta_, sinTheta_, upper_, total_;
};

template <typename T> class BeckmannDistribution : public SmithMicrofacet<BeckmannDistribution<T>, T> {
  using Base = SmithMicrofacet<BeckmannDistribution<T>, T>;

 public:
  BeckmannDistribution(T alphaX, T alphaY) : Base(alphaX, alphaY) {}
  using Base::alphaX;
  using Base::alphaY;

  // D(m) = exp(-tan^2 theta (cos^2 phi / ax^2 + sin^2 phi / ay^2)) / (pi ax ay cos^4 theta)
  // (Walter et al. 2007 eq. 25, anisotropic form Heitz 2014).
  T D(const Vec3<T>& m) const {
    using std::exp;
    if (!(m.z > T(0))) return T(0);
    const T cos2Theta = m.z * m.z;
    const T exponent = (sqr(m.x / alphaX()) + sqr(m.y / alphaY())) / cos2Theta;
    const T gaussian = exp(-exponent);
    // Also catches cos^4 underflowing to 0 near the horizon (0 / 0 otherwise).
    if (gaussian == T(0)) return T(0);
    return gaussian / (T(Pi) * alphaX() * alphaY() * cos2Theta * cos2Theta);
  }

  // |cos| Lambda with Lambda = (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)),
  // a = 1 / (alpha tan theta) (Heitz 2014). With s = alpha sin theta = a^-1 cos theta
  // the division by a disappears: |cos| Lambda = s exp(-a^2) / (2 sqrt(pi)) - |cos| erfc(a) / 2.
  T backfacingArea(const Vec3<T>& w) const {
    using std::abs;
    using std::erfc;
    using std::exp;
    const T s = safeSqrt(sqr(alphaX() * w.x) + sqr(alphaY() * w.y));
    if (!(s > T(0))) return T(0);
    const T cosTheta = abs(w.z);
    const T a = cosTheta / s;
    const T area = s * exp(-a * a) / T(2.0 * SqrtPi) - cosTheta * erfc(a) / T(2);
    // Near the pole both terms are ~exp(-a^2) and their difference can round below 0.
    return area > T(0) ? area : T(0);
  }

  // Heitz & d'Eon 2014: stretch w to the alpha = 1 configuration, rotate it into the
  // xz-plane, sample the visible slope there (x exactly by inverting its CDF; y, independent
  // of x, Gaussian with variance 1/2), rotate back and unstretch the slope.
  // Slopes follow m = (-x, -y, 1) / |.|.
  Vec3d sampleVisible(const Vec3d& w, const Vec2d& u) const requires std::same_as<T, double> {
    const IncidentFrame frame = incidentFrame(w);
    const double xs = frame.slopeX.invert(u.x);
    const double ys = -inverseErfc(2.0 * u.y);  // (1 + erf(ys)) / 2 = u.y
    const double slopeX = alphaX() * (frame.cosPhi * xs - frame.sinPhi * ys);
    const double slopeY = alphaY() * (frame.sinPhi * xs + frame.cosPhi * ys);
    return glm::normalize(Vec3d(-slopeX, -slopeY, 1.0));
  }

  Vec2d invertVisible(const Vec3d& w, const Vec3d& m) const requires std::same_as<T, double> {
    if (!(m.z > 0)) return {1.0, 0.5};
    const IncidentFrame frame = incidentFrame(w);
    const double sx = -m.x / (m.z * alphaX()), sy = -m.y / (m.z * alphaY());
    const double xs = frame.cosPhi * sx + frame.sinPhi * sy;
    const double ys = -frame.sinPhi * sx + frame.cosPhi * sy;
    return {frame.slopeX.cdf(xs), 0.5 * std::erfc(-ys)};
  }

  // m with density D(m) cos theta_m: the slopes are Gaussian, P22 = exp(-r^2) / pi in the
  // stretched plane, with radial CDF 1 - exp(-r^2) (Walter et al. 2007 eq. 28).
  Vec3d sampleClassic(const Vec2d& u) const requires std::same_as<T, double> {
    const double r = std::sqrt(-std::log1p(-u.x));
    const double phi = 2.0 * Pi * u.y;
    return glm::normalize(Vec3d(alphaX() * r * std::cos(phi), alphaY() * r * std::sin(phi), 1.0));
  }

  Vec2d invertClassic(const Vec3d& m) const requires std::same_as<T, double> {
    const double qx = m.x / alphaX(), qy = m.y / alphaY();
    if (!(m.z > 0)) return {1.0, azimuthToUnit(qy, qx)};
    const double r2 = (qx * qx + qy * qy) / (m.z * m.z);
    return {-std::expm1(-r2), azimuthToUnit(qy, qx)};
  }

 private:
  // w stretched to the alpha = 1 configuration: its polar angle (through cos and sin, taken
  // from the components so small angles keep their precision) and azimuth.
  struct IncidentFrame {
    double cosPhi, sinPhi;
    BeckmannVisibleSlopeX slopeX;
  };
  IncidentFrame incidentFrame(const Vec3d& w) const requires std::same_as<T, double> {
    const Vec3d ws = glm::normalize(Vec3d(alphaX() * w.x, alphaY() * w.y, w.z));
    const double sinTheta = std::sqrt(ws.x * ws.x + ws.y * ws.y);
    const double cosPhi = sinTheta > 0 ? ws.x / sinTheta : 1.0;
    const double sinPhi = sinTheta > 0 ? ws.y / sinTheta : 0.0;
    return {cosPhi, sinPhi, BeckmannVisibleSlopeX(std::max(0.0, ws.z), sinTheta)};
  }
};

// The MicrofacetType of a distribution class (for tables and caches keyed by it).
template <typename Distribution> constexpr MicrofacetType microfacetTypeOf() {
  static_assert(std::is_same_v<Distribution, GgxDistribution<double>> ||
                std::is_same_v<Distribution, BeckmannDistribution<double>>);
  return std::is_same_v<Distribution, GgxDistribution<double>> ? MicrofacetType::Ggx
                                                               : MicrofacetType::Beckmann;
}

}  // namespace scatterlab
