// Directional albedo of single-scattering microfacet reflection off a dielectric,
//   E(wi) = integral of D(h) F(wi.h) G2(wi, wo) / (4 cos_i cos_o) cos_o dwo
// (Walter et al. 2007 eq. 20 with Smith height-correlated G2, Heitz 2014 eq. 99), by quadrature
// and as a table over the incident direction. The energy-coupled diffuse term of a layered or
// "coupled specular-matte" model (Kelemen & Szirmay-Kalos 2001; rough_plastic.h) weights its
// light by 1 - E, which needs E at every evaluation; the same tables serve multiple-scattering
// compensation (Kulla & Conty 2017) if a model adds it.
//
// Quadrature. With wo = reflect(wi, m), dwo = 4 |wo.m| dm (Walter et al. 2007 eq. 14) and
// wo.m = wi.m, so
//   E(wi) = integral over {m : wo.z > 0} of D(m) F(wi.m) G2(wi, wo) (wi.m) / cos_i dm.
// The normals are parameterised in the stretched (alpha = 1) configuration, m = M n / |M n|,
// M = diag(alpha_x, alpha_y, 1), n = (sin psi cos phi, sin psi sin phi, cos psi), with the
// Jacobian of a linearly transformed direction dm = alpha_x alpha_y / |M n|^3 dn (Heitz et al.
// 2016, "Real-Time Polygonal-Light Shading with Linearly Transformed Cosines", section 3):
// there D(m) dm is spread over the whole hemisphere of n for every alpha, so a fixed rule
// resolves a lobe of alpha 0.001 as well as one of alpha 1. Along one azimuth, m turns on the
// great circle through the normal and h = (alpha_x cos phi, alpha_y sin phi, 0) / A,
// A = |(alpha_x cos phi, alpha_y sin phi)|, by the angle psi' with tan psi' = A tan psi; there
// wo.z = cos_i cos 2psi' + (wi.h) sin 2psi', which is positive exactly for
// psi' < (delta + pi/2) / 2, delta = atan2(wi.h, cos_i) (and wi.m > 0 then follows). So each
// azimuth is a smooth integral over psi in [0, psi_max], done by Gauss-Legendre after
// psi = psi_max (1 - (1 - t)^2), which puts nodes where GGX's long tail meets the horizon; the
// azimuth, where psi_max turns fast for grazing wi, is integrated adaptively.
//
// Table. For isotropic roughness E depends on cos_i only. It is tabulated as the ratio
// r = E / F(cos_i), which is ~1 for smooth surfaces and smooth in cos_i for rough ones (the
// Fresnel curve is put back exactly at lookup), on nodes uniform in
// s = log(cos_i + c) + cos_i / 0.1: log-spaced toward grazing, where masking changes E on the
// scale of alpha (c = min(alpha / 20, 0.002)), and about 0.01 apart near the normal; Catmull-Rom
// interpolation. Measured against the quadrature from cos_i = 1e-4 to 1, the table is within
// 3e-5 of it for alpha 0.001..1 and eta 1.1..4 (rough_plastic_test.cpp); a table has ~140
// nodes and takes ~0.1 s to build. The cosine-weighted average Ebar = (1/pi) integral of
// E cos dw is integrated from the interpolant itself, so that a model normalised by 1 - Ebar
// is normalised exactly for the E it uses. Anisotropic roughness is not tabulated: at grazing
// incidence E then changes with the azimuth on the scale alpha_x / alpha_y, which no small
// table resolves (9 or 17 azimuths left errors of 4e-3 to 0.4).
#pragma once

#include <memory>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "materials/bsdf/fresnel.h"
#include "materials/bsdf/microfacet.h"
#include "materials/core/gauss_legendre.h"
#include "materials/core/quadrature.h"
#include "materials/core/spherical.h"

namespace scatterlab {

// E(wi) for wi.z > 0 by the quadrature above: within 2e-6 of an independent integral (the
// classic sampler's) for alpha 0.001..1, eta 1.1..2.4, up to 89.9 degrees. 0 for wi.z <= 0.
template <typename Distribution>
double dielectricReflectionAlbedo(const Distribution& distribution, double eta, const Vec3d& wi) {
  if (!(wi.z > 0) || eta == 1.0) return 0.0;
  const double ax = distribution.alphaX(), ay = distribution.alphaY();
  const GaussLegendreRule<24>& rule = gaussLegendre<24>();
  const auto alongAzimuth = [&](double phi) {
    const double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    const double a = std::hypot(ax * cosPhi, ay * sinPhi);
    const Vec3d h(ax * cosPhi / a, ay * sinPhi / a, 0.0);
    const double delta = std::atan2(glm::dot(wi, h), wi.z);
    const double psiMax = std::atan(std::tan(0.5 * (delta + PiOver2)) / a);
    double sum = 0.0;
    for (size_t k = 0; k < rule.nodes.size(); ++k) {
      const double oneMinusT = 1.0 - rule.nodes[k];
      const double psi = psiMax * (1.0 - oneMinusT * oneMinusT);
      const double sinPsi = std::sin(psi);
      const Vec3d stretched(ax * sinPsi * cosPhi, ay * sinPsi * sinPhi, std::cos(psi));
      const double length = glm::length(stretched);
      const Vec3d m = stretched / length;
      const double cosIM = glm::dot(wi, m);
      if (!(cosIM > 0)) continue;
      const Vec3d wo = reflect(wi, m);
      if (!(wo.z > 0)) continue;
      const double jacobian = ax * ay / (length * length * length) * sinPsi * 2.0 * oneMinusT;
      sum += rule.weights[k] * jacobian * distribution.D(m) * fresnelDielectric(cosIM, eta) *
             distribution.G2(wi, wo) * cosIM / wi.z;
    }
    return sum * psiMax;
  };
  QuadratureOptions options;
  options.relativeTolerance = 1e-6;
  options.absoluteTolerance = 1e-9;
  options.minDepth = 4;
  options.maxDepth = 30;
  // Mirror symmetry about the plane of incidence for isotropic roughness: half the circle.
  if (distribution.isotropic() && wi.y == 0.0) return 2.0 * adaptiveSimpson(alongAzimuth, 0.0, Pi, options);
  return adaptiveSimpson(alongAzimuth, 0.0, 2.0 * Pi, options);
}

// E tabulated for one isotropic distribution and eta (see the header comment). A lookup costs
// one Fresnel evaluation, a logarithm and a 4-point Catmull-Rom interpolation.
class DielectricReflectionAlbedoTable {
 public:
  // Throws std::invalid_argument for anisotropic roughness or eta < 1.
  template <typename Distribution>
  DielectricReflectionAlbedoTable(const Distribution& distribution, double eta)
      : eta_(eta), offset_(std::min(0.05 * distribution.alphaX(), 2e-3)) {
    if (!distribution.isotropic())
      throw std::invalid_argument(
          "the dielectric reflection albedo is tabulated for isotropic roughness only");
    if (!(eta >= 1.0)) throw std::invalid_argument("the albedo table needs eta >= 1");
    placeNodes();
    ratio_.resize(nodeCos_.size());
    for (size_t i = 0; i < nodeCos_.size(); ++i) {
      const double cosTheta = nodeCos_[i];
      const Vec3d wi(safeSqrt(1.0 - cosTheta * cosTheta), 0.0, cosTheta);
      const double fresnel = fresnelDielectric(cosTheta, eta);
      ratio_[i] = fresnel > 0 ? dielectricReflectionAlbedo(distribution, eta, wi) / fresnel : 0.0;
    }
    average_ = integrateAverage();
  }

  // E(w) for a unit direction w; 0 for w.z <= 0. In [0, 1].
  double operator()(const Vec3d& w) const;
  // Ebar = (1/pi) integral over the hemisphere of E(w) cos theta dw, of this interpolant.
  double hemisphericalAverage() const { return average_; }
  double eta() const { return eta_; }
  int nodeCount() const { return int(nodeCos_.size()); }

 private:
  void placeNodes();
  double s(double cosTheta) const;
  double integrateAverage() const;

  double eta_, offset_;
  double s0_ = 0, ds_ = 0;
  std::vector<double> nodeCos_;  // cos theta at the nodes, uniform in s
  std::vector<double> ratio_;    // E / F at the nodes
  double average_ = 0;
};

namespace detail {
std::shared_ptr<const DielectricReflectionAlbedoTable> findAlbedoTable(int family, double alphaX,
                                                                       double alphaY, double eta);
void storeAlbedoTable(int family, double alphaX, double alphaY, double eta,
                      std::shared_ptr<const DielectricReflectionAlbedoTable> table);
}  // namespace detail

// The table for (distribution, eta), built once and shared: models with the same roughness
// and index (a suite's repeated builds, the negative controls) reuse it.
template <typename Distribution>
std::shared_ptr<const DielectricReflectionAlbedoTable> sharedDielectricReflectionAlbedo(
    const Distribution& distribution, double eta) {
  constexpr int family = std::is_same_v<Distribution, GgxDistribution<double>>        ? 0
                         : std::is_same_v<Distribution, BeckmannDistribution<double>> ? 1
                                                                                      : -1;
  static_assert(family >= 0, "no albedo table cache for this distribution");
  const double ax = distribution.alphaX(), ay = distribution.alphaY();
  if (auto table = detail::findAlbedoTable(family, ax, ay, eta)) return table;
  auto table = std::make_shared<const DielectricReflectionAlbedoTable>(distribution, eta);
  detail::storeAlbedoTable(family, ax, ay, eta, table);
  return table;
}

}  // namespace scatterlab
