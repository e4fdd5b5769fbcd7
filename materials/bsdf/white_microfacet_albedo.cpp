#include "materials/bsdf/white_microfacet_albedo.h"

#include <functional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "materials/core/shared_cache.h"

namespace scatterlab {

const std::array<double, WhiteAlbedoGrid::NodeCount>& whiteAlbedoTable(MicrofacetType type) {
  return type == MicrofacetType::Ggx ? GgxWhiteAlbedoTable : BeckmannWhiteAlbedoTable;
}

double computeWhiteAlbedoNode(MicrofacetType type, int alphaIndex, int cosIndex,
                              const QuadratureOptions& options) {
  const double alpha = WhiteAlbedoGrid::alphaNode(alphaIndex);
  const double mu = WhiteAlbedoGrid::cosAt(WhiteAlbedoGrid::cosNodeCoordinate(cosIndex), alpha);
  const Vec3d wi(safeSqrt(1.0 - mu * mu), 0.0, mu);
  if (type == MicrofacetType::Ggx)
    return whiteMicrofacetAlbedo(GgxDistribution<double>(alpha, alpha), wi, options);
  return whiteMicrofacetAlbedo(BeckmannDistribution<double>(alpha, alpha), wi, options);
}

namespace {

// The committed table's interpolant at alpha, on the u nodes: one row, which a 1-D
// Catmull-Rom then interpolates exactly as the 2-D interpolant would (tensor product).
std::vector<double> isotropicRow(MicrofacetType type, double alpha) {
  const auto& nodes = whiteAlbedoTable(type);
  const CatmullRomTable2D committed(WhiteAlbedoGrid::AlphaNodes, WhiteAlbedoGrid::CosNodes,
                                    std::vector<double>(nodes.begin(), nodes.end()));
  const double s = WhiteAlbedoGrid::alphaCoordinate(alpha);
  std::vector<double> row(WhiteAlbedoGrid::CosNodes);
  for (int j = 0; j < WhiteAlbedoGrid::CosNodes; ++j)
    row[j] = committed(s, WhiteAlbedoGrid::cosNodeCoordinate(j));
  return row;
}

template <typename Distribution>
std::vector<double> anisotropicNodes(const Distribution& distribution, int azimuthNodes,
                                     const std::function<double(double)>& projectedAlphaAt) {
  const double ax = distribution.alphaX(), ay = distribution.alphaY();
  std::vector<double> values;
  values.reserve(size_t(azimuthNodes) * WhiteAlbedoGrid::CosNodes);
  for (int k = 0; k < azimuthNodes; ++k) {
    const double a = projectedAlphaAt(double(k) / (azimuthNodes - 1));
    // a^2 = ax^2 cos^2 phi + ay^2 sin^2 phi, solved for cos^2 phi.
    const double cos2Phi = std::clamp((ay * ay - a * a) / (ay * ay - ax * ax), 0.0, 1.0);
    const double cosPhi = std::sqrt(cos2Phi), sinPhi = std::sqrt(1.0 - cos2Phi);
    for (int j = 0; j < WhiteAlbedoGrid::CosNodes; ++j) {
      const double mu = WhiteAlbedoGrid::cosAt(WhiteAlbedoGrid::cosNodeCoordinate(j), a);
      const double sinTheta = safeSqrt(1.0 - mu * mu);
      values.push_back(
          whiteMicrofacetAlbedoFixed(distribution, Vec3d(sinTheta * cosPhi, sinTheta * sinPhi, mu)));
    }
  }
  return values;
}

QuadratureOptions averageQuadrature(double relativeTolerance) {
  QuadratureOptions q;
  q.relativeTolerance = relativeTolerance;
  q.absoluteTolerance = 1e-300;  // relative only: the loss is ~1e-6 at alpha 0.001
  q.minDepth = 1;
  q.maxDepth = 30;
  return q;
}

// See SharedCache: bounded, for fits that move the roughness continuously.
constexpr size_t MaxCacheEntries = 64;

}  // namespace

WhiteMicrofacetAlbedo::WhiteMicrofacetAlbedo(MicrofacetType type, double alphaX, double alphaY)
    : type_(type), alphaX_(alphaX), alphaY_(alphaY) {
  for (const double alpha : {alphaX, alphaY})
    if (!(alpha > 0.0 && alpha <= WhiteAlbedoGrid::AlphaMax))
      throw std::invalid_argument(
          "the multiple-scattering albedo is tabulated for roughness in (0, 1], got " +
          std::to_string(alpha));
  if (alphaX == alphaY) {
    table_ = CatmullRomTable2D(1, WhiteAlbedoGrid::CosNodes, isotropicRow(type, alphaX));
  } else {
    const auto projected = [this](double w) {
      const double r = std::sqrt(alphaX_) + w * (std::sqrt(alphaY_) - std::sqrt(alphaX_));
      return r * r;
    };
    std::vector<double> values =
        type == MicrofacetType::Ggx
            ? anisotropicNodes(GgxDistribution<double>(alphaX, alphaY), AnisotropicAzimuthNodes, projected)
            : anisotropicNodes(BeckmannDistribution<double>(alphaX, alphaY), AnisotropicAzimuthNodes,
                               projected);
    table_ = CatmullRomTable2D(AnisotropicAzimuthNodes, WhiteAlbedoGrid::CosNodes, std::move(values));
  }
  averageLoss_ = integrateAverageLoss();
}

std::shared_ptr<const WhiteMicrofacetAlbedo> WhiteMicrofacetAlbedo::shared(MicrofacetType type, double alphaX,
                                                                           double alphaY) {
  static SharedCache<std::tuple<MicrofacetType, double, double>, WhiteMicrofacetAlbedo> cache(
      MaxCacheEntries);
  return cache.get({type, alphaX, alphaY},
                   [&] { return std::make_shared<const WhiteMicrofacetAlbedo>(type, alphaX, alphaY); });
}

double WhiteMicrofacetAlbedo::projectedAlpha(double cos2Phi) const {
  return std::sqrt(alphaX_ * alphaX_ * cos2Phi + alphaY_ * alphaY_ * (1.0 - cos2Phi));
}

double WhiteMicrofacetAlbedo::azimuthCoordinate(double projected) const {
  return (std::sqrt(projected) - std::sqrt(alphaX_)) / (std::sqrt(alphaY_) - std::sqrt(alphaX_));
}

double WhiteMicrofacetAlbedo::operator()(const Vec3d& w) const {
  if (!(w.z > 0)) return 1.0;
  const double mu = std::min(w.z, 1.0);
  double value;
  if (isotropic()) {
    value = table_(0.0, WhiteAlbedoGrid::cosCoordinate(mu, alphaX_));
  } else {
    // E is even in x and in y: only cos^2 phi matters. At the pole any azimuth will do.
    const double r2 = w.x * w.x + w.y * w.y;
    const double a = projectedAlpha(r2 > 0 ? w.x * w.x / r2 : 1.0);
    value = table_(azimuthCoordinate(a), WhiteAlbedoGrid::cosCoordinate(mu, a));
  }
  return std::clamp(value, 0.0, 1.0);
}

double WhiteMicrofacetAlbedo::integrateAverageLoss() const {
  // 2 integral_0^1 (1 - E) mu dmu along one azimuth, node interval by node interval: the
  // interpolant is a cubic in u inside each.
  const auto alongAzimuth = [this](double cosPhi, double sinPhi, double a) {
    const QuadratureOptions options = averageQuadrature(1e-10);
    double sum = 0.0;
    for (int j = 0; j + 1 < WhiteAlbedoGrid::CosNodes; ++j) {
      const double lo = WhiteAlbedoGrid::cosAt(WhiteAlbedoGrid::cosNodeCoordinate(j), a);
      const double hi = WhiteAlbedoGrid::cosAt(WhiteAlbedoGrid::cosNodeCoordinate(j + 1), a);
      sum += adaptiveSimpson(
          [&](double mu) {
            const double s = safeSqrt(1.0 - mu * mu);
            return loss(Vec3d(s * cosPhi, s * sinPhi, mu)) * mu;
          },
          lo, hi, options);
    }
    return 2.0 * sum;
  };
  if (isotropic()) return alongAzimuth(1.0, 0.0, alphaX_);
  // (1/pi) integral over phi in [0, 2 pi) = (2/pi) integral over [0, pi/2] (E even in x and y),
  // of the azimuth's 2 integral (1 - E) mu dmu; pieces between the azimuths of the table's rows.
  const auto atAzimuth = [&](double phi) {
    const double c = std::cos(phi), s = std::sin(phi);
    return alongAzimuth(c, s, projectedAlpha(c * c));
  };
  std::vector<double> breaks;
  for (int k = 0; k < table_.rows(); ++k) {
    const double r =
        std::sqrt(alphaX_) + double(k) / (table_.rows() - 1) * (std::sqrt(alphaY_) - std::sqrt(alphaX_));
    const double a = r * r;
    const double cos2Phi =
        std::clamp((alphaY_ * alphaY_ - a * a) / (alphaY_ * alphaY_ - alphaX_ * alphaX_), 0.0, 1.0);
    breaks.push_back(std::acos(std::sqrt(cos2Phi)));
  }
  breaks.front() = 0.0;
  breaks.back() = PiOver2;
  const QuadratureOptions options = averageQuadrature(1e-9);
  double sum = 0.0;
  for (size_t k = 0; k + 1 < breaks.size(); ++k)
    sum += adaptiveSimpson(atAzimuth, breaks[k], breaks[k + 1], options);
  return (2.0 / Pi) * sum;
}

}  // namespace scatterlab
