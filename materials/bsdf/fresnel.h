// Fresnel reflectance: the fraction of light a smooth interface reflects, unpolarised.
//
// Kernels are templated on the scalar T (double, or ceres::Jet for fitting): math calls are
// unqualified after `using std::...`, and every branch that guards a singular point keeps
// the value AND the derivative finite (docs/design.md, "One model code").
#pragma once

#include "materials/core/math.h"

namespace scatterlab {

// Exact unpolarised reflectance of a dielectric interface (Fresnel equations with Snell's
// law; pbrt-v4 FrDielectric). eta = eta_t / eta_i for light arriving from the side the
// normal points to (cosThetaI > 0). cosThetaI < 0 means the light arrives from the other
// side: the roles of the two media swap, so the relative index inverts.
template <typename T> T fresnelDielectric(T cosThetaI, T eta) {
  cosThetaI = clampTo(cosThetaI, -1.0, 1.0);
  if (cosThetaI < T(0)) {
    eta = T(1) / eta;
    cosThetaI = -cosThetaI;
  }
  const T sin2ThetaI = T(1) - cosThetaI * cosThetaI;
  const T sin2ThetaT = sin2ThetaI / (eta * eta);
  // Total internal reflection: Snell's law has no real transmitted angle.
  if (sin2ThetaT >= T(1)) return T(1);
  const T cosThetaT = safeSqrt(T(1) - sin2ThetaT);
  // Both denominators vanish only when cosThetaI = cosThetaT = 0, which is the TIR case above.
  const T rParallel = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
  const T rPerpendicular = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
  return (sqr(rParallel) + sqr(rPerpendicular)) / T(2);
}

// Exact unpolarised reflectance of a conductor with complex relative index eta + i k, in real
// arithmetic (the form of pbrt-v3 FrConductor and Mitsuba's fresnel_conductor; derivation in
// S. Lagarde 2013, "Memo on Fresnel equations"). With a^2 + b^2 = |eta^2 - sin^2 theta| for
// the complex eta, the s and p amplitudes reduce to the Rs and Rp ratios below. A conductor is
// opaque, so the side the light comes from only enters through |cos theta|. k = 0 reproduces
// fresnelDielectric, including total internal reflection.
template <typename T> T fresnelConductor(T cosThetaI, const T& eta, const T& k) {
  using std::abs;
  const T cosI = clampTo(T(abs(cosThetaI)), 0.0, 1.0);
  const T cos2 = cosI * cosI;
  const T sin2 = T(1) - cos2;
  const T eta2 = eta * eta;
  const T k2 = k * k;
  const T t0 = eta2 - k2 - sin2;
  // safeSqrt: at k = 0 and eta = sin theta the radicands reach 0, where sqrt's slope is infinite.
  const T a2PlusB2 = safeSqrt(t0 * t0 + T(4) * eta2 * k2);
  const T a = safeSqrt(T(0.5) * (a2PlusB2 + t0));
  const T t1 = a2PlusB2 + cos2;
  const T t2 = T(2) * cosI * a;
  // t1 + t2 = 0 needs eta = k = 0 at grazing incidence: a perfect mirror in the limit.
  if (!(t1 + t2 > T(0))) return T(1);
  const T rs = (t1 - t2) / (t1 + t2);
  const T t3 = cos2 * a2PlusB2 + sin2 * sin2;
  const T t4 = t2 * sin2;
  // t3 + t4 >= cos^2 |eta^2 - sin^2| + sin^4 > 0 except in the same degenerate case.
  if (!(t3 + t4 > T(0))) return T(1);
  const T rp = rs * (t3 - t4) / (t3 + t4);
  return (rs + rp) / T(2);
}

// Per channel, for a conductor given as linear-RGB eta and k.
template <typename T> RgbT<T> fresnelConductor(const T& cosThetaI, const RgbT<T>& eta, const RgbT<T>& k) {
  return {fresnelConductor(cosThetaI, eta.x, k.x), fresnelConductor(cosThetaI, eta.y, k.y),
          fresnelConductor(cosThetaI, eta.z, k.z)};
}

// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering", eq. 24: the
// reflectance at normal incidence F0 raised toward 1 by (1 - cos theta)^5. Only for models
// that are defined with it (Ngan's Cook-Torrance, Disney), not as an approximation of the
// exact terms above.
template <typename T> T fresnelSchlick(const T& f0, const T& cosTheta) {
  const T m = T(1) - clampTo(cosTheta, 0.0, 1.0);
  const T m2 = m * m;
  return f0 + (T(1) - f0) * (m2 * m2 * m);
}

template <typename T> RgbT<T> fresnelSchlick(const RgbT<T>& f0, const T& cosTheta) {
  return {fresnelSchlick(f0.x, cosTheta), fresnelSchlick(f0.y, cosTheta), fresnelSchlick(f0.z, cosTheta)};
}

}  // namespace scatterlab
