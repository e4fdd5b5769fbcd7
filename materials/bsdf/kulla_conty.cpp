#include "materials/bsdf/kulla_conty.h"

#include <optional>
#include <vector>

namespace scatterlab {

namespace {

// mu(v) = c a t / (1 + c a - t), t = v^2 (the table's Moebius map, white_microfacet_albedo.h),
// and its derivative dmu/dv = c a (1 + c a) 2 v / (1 + c a - t)^2.
struct CosMap {
  double ca;
  double cosAt(double v) const {
    const double t = v * v;
    return std::min(1.0, ca * t / (1.0 + ca - t));
  }
  double derivative(double v) const {
    const double denominator = 1.0 + ca - v * v;
    return ca * (1.0 + ca) * 2.0 * v / (denominator * denominator);
  }
  double coordinate(double mu) const {
    const double t = std::min(1.0, mu * (1.0 + ca) / (mu + ca));
    return std::sqrt(t);
  }
};

CosMap cosMap(double alpha) { return {WhiteAlbedoGrid::MoebiusScale * alpha}; }

double wrappedAzimuth(const Vec3d& w) {
  const double phi = std::atan2(w.y, w.x);
  return phi < 0 ? phi + 2.0 * Pi : phi;
}

}  // namespace

double LossLobeSampler::projectedAlpha(double cosPhi, double sinPhi) const {
  return std::sqrt(sqr(alphaX_ * cosPhi) + sqr(alphaY_ * sinPhi));
}

LossLobeSampler::LossLobeSampler(const std::function<double(const Vec3d&)>& loss, double averageLoss,
                                 double alphaX, double alphaY)
    : alphaX_(alphaX), alphaY_(alphaY) {
  const int azimuths = alphaX == alphaY ? 2 : AnisotropicAzimuthNodes;
  std::vector<double> phiEdges(azimuths), vEdges(CosNodes), values;
  for (int i = 0; i < azimuths; ++i) phiEdges[i] = 2.0 * Pi * i / (azimuths - 1);
  for (int j = 0; j < CosNodes; ++j) vEdges[j] = double(j) / (CosNodes - 1);
  // The cosine share: a cosine lobe integrates to pi over the hemisphere, the loss lobe to
  // pi (1 - E_avg).
  const double floor = averageLoss > 0 ? CosineShare / (1.0 - CosineShare) * averageLoss : 1.0;
  values.reserve(size_t(azimuths) * CosNodes);
  for (int i = 0; i < azimuths; ++i) {
    const double cosPhi = std::cos(phiEdges[i]), sinPhi = std::sin(phiEdges[i]);
    const CosMap map = cosMap(projectedAlpha(cosPhi, sinPhi));
    for (int j = 0; j < CosNodes; ++j) {
      const double mu = map.cosAt(vEdges[j]);
      const double sinTheta = safeSqrt(1.0 - mu * mu);
      const double lossHere = std::max(0.0, loss(Vec3d(sinTheta * cosPhi, sinTheta * sinPhi, mu)));
      values.push_back((lossHere + floor) * mu * map.derivative(vEdges[j]));
    }
  }
  density_ = PiecewiseBilinear2D(std::move(phiEdges), std::move(vEdges), std::move(values));
}

KullaContyLobe::KullaContyLobe(std::shared_ptr<const WhiteMicrofacetAlbedo> albedo)
    : albedo_(std::move(albedo)),
      sampler_([this](const Vec3d& w) { return albedo_->loss(w); }, albedo_->averageLoss(), albedo_->alphaX(),
               albedo_->alphaY()) {}

std::optional<Vec3d> LossLobeSampler::sample(const Vec2d& u) const {
  const Vec2d point = density_.sample(u);
  const double phi = point.x, cosPhi = std::cos(phi), sinPhi = std::sin(phi);
  const double mu = cosMap(alphaX_ == alphaY_ ? alphaX_ : projectedAlpha(cosPhi, sinPhi)).cosAt(point.y);
  if (!(mu > 0)) return std::nullopt;
  const double sinTheta = safeSqrt(1.0 - mu * mu);
  return Vec3d(sinTheta * cosPhi, sinTheta * sinPhi, mu);
}

double LossLobeSampler::pdf(const Vec3d& wo) const {
  if (!(wo.z > 0)) return 0.0;
  // Isotropic: the density does not depend on the azimuth (its two rows are equal).
  const bool isotropic = alphaX_ == alphaY_;
  const double r = isotropic ? 0.0 : std::sqrt(wo.x * wo.x + wo.y * wo.y);
  const double cosPhi = r > 0 ? wo.x / r : 1.0, sinPhi = r > 0 ? wo.y / r : 0.0;
  const CosMap map = cosMap(isotropic ? alphaX_ : projectedAlpha(cosPhi, sinPhi));
  const double v = map.coordinate(std::min(wo.z, 1.0));
  const double jacobian = map.derivative(v);  // dmu/dv; dw = dmu dphi
  if (!(jacobian > 0)) return 0.0;
  return density_.density(r > 0 ? wrappedAzimuth(wo) : 0.0, v) / jacobian;
}

}  // namespace scatterlab
