#include "materials/measured/half_vector_sampler.h"

#include <stdexcept>

#include "materials/bsdf/half_vector.h"
#include "materials/core/lobe_choice.h"
#include "materials/core/warp.h"
#include "materials/measured/merl_format.h"

namespace scatterlab {

namespace {

// cos and sin of w's azimuth; (1, 0) at the pole, where any azimuth serves as long as
// sample() and pdf() agree.
Vec2d azimuthOf(const Vec3d& w) {
  const double s = std::sqrt(w.x * w.x + w.y * w.y);
  return s > 0 ? Vec2d(w.x / s, w.y / s) : Vec2d(1.0, 0.0);
}

// The grid coordinates of h relative to wi: 1 - cos theta_h (as sin^2 / (1 + cos), exact next
// to the pole) and phi_h - phi_i in (-pi, pi].
Vec2d gridCoordinates(const Vec3d& h, const Vec2d& azimuthI) {
  const double x = (h.x * h.x + h.y * h.y) / (1.0 + h.z);
  const double phi = std::atan2(-h.x * azimuthI.y + h.y * azimuthI.x, h.x * azimuthI.x + h.y * azimuthI.y);
  return {x, phi};
}

}  // namespace

HalfVectorSampler::HalfVectorSampler(const Brdf& brdf, const HalfVectorSamplerOptions& options)
    : options_(options) {
  if (options.incidentNodes < 1 || options.phiCells < 1 || !(options.cosineFraction >= 0) ||
      !(options.cosineFraction < 1))
    throw std::invalid_argument("HalfVectorSampler: needs >= 1 node and phi cell, cosine fraction in [0, 1)");
  constexpr int ThetaEdges = merl::ThetaHalfCells + 1;
  const int phiEdges = options.phiCells + 1;
  std::vector<double> xEdges(ThetaEdges), phiEdge(static_cast<size_t>(phiEdges));
  std::vector<double> sinEdge(ThetaEdges), cosEdge(ThetaEdges);
  for (int i = 0; i < ThetaEdges; ++i) {
    const double theta = merl::thetaHalfAt(i);
    xEdges[size_t(i)] = 2.0 * sqr(std::sin(0.5 * theta));  // 1 - cos, without cancellation
    sinEdge[size_t(i)] = std::sin(theta);
    cosEdge[size_t(i)] = std::cos(theta);
  }
  for (int j = 0; j < phiEdges; ++j) phiEdge[size_t(j)] = -Pi + 2.0 * Pi * j / options.phiCells;

  const double nodeWidth = PiOver2 / options.incidentNodes;
  nodes_.reserve(size_t(options.incidentNodes));
  for (int k = 0; k < options.incidentNodes; ++k) {
    const double thetaI = (k + 0.5) * nodeWidth;
    const Vec3d wi(std::sin(thetaI), 0.0, std::cos(thetaI));
    const auto target = [&](const Vec3d& h) {
      const Vec3d wo = reflect(wi, h);
      if (!(wo.z > 0)) return 0.0;
      const Rgb f = brdf(wi, wo);
      const double value = (f.x + f.y + f.z) / 3.0 * wo.z * 4.0 * glm::dot(wi, h);
      return std::isfinite(value) && value > 0 ? value : 0.0;
    };
    std::vector<double> values(size_t(ThetaEdges) * size_t(phiEdges));
    const double pole = target(Vec3d(0, 0, 1));  // one value for every phi: continuous at the pole
    for (int j = 0; j < phiEdges; ++j) values[size_t(j)] = pole;
    for (int i = 1; i < ThetaEdges; ++i) {
      for (int j = 0; j < options.phiCells; ++j) {
        const double phi = phiEdge[size_t(j)];
        values[size_t(i) * size_t(phiEdges) + size_t(j)] = target(Vec3d(
            sinEdge[size_t(i)] * std::cos(phi), sinEdge[size_t(i)] * std::sin(phi), cosEdge[size_t(i)]));
      }
      values[size_t(i) * size_t(phiEdges) + size_t(options.phiCells)] =
          values[size_t(i) * size_t(phiEdges)];  // periodic
    }
    nodes_.emplace_back(xEdges, phiEdge, std::move(values));
  }
}

HalfVectorSampler::NodeWeights HalfVectorSampler::nodeWeights(double cosThetaI) const {
  const int last = options_.incidentNodes - 1;
  const double x = safeAcos(cosThetaI) / (PiOver2 / options_.incidentNodes) - 0.5;
  if (!(x > 0)) return {0, 0, 0.0};
  if (x >= last) return {last, last, 0.0};
  const int k = int(x);
  return {k, k + 1, x - k};
}

double HalfVectorSampler::pdf(const Vec3d& wi, const Vec3d& wo) const {
  if (!(wi.z > 0) || !(wo.z > 0)) return 0.0;
  const double cosine = cosineHemispherePdf(wo.z);
  const Vec3d h = reflectionHalfVector(wi, wo);
  const Vec2d grid = gridCoordinates(h, azimuthOf(wi));
  const auto nodeDensity = [&](int node) {
    const PiecewiseBilinear2D& distribution = nodes_[size_t(node)];
    if (!(distribution.total() > 0)) return cosine;  // nothing tabulated: cosine instead
    return reflectedDensity(distribution.density(grid.x, grid.y), wo, h);
  };
  const NodeWeights w = nodeWeights(wi.z);
  double table = nodeDensity(w.first);
  if (w.secondWeight > 0) table = (1.0 - w.secondWeight) * table + w.secondWeight * nodeDensity(w.second);
  return options_.cosineFraction * cosine + (1.0 - options_.cosineFraction) * table;
}

std::optional<Vec3d> HalfVectorSampler::sample(const Vec3d& wi, double uLobe, const Vec2d& u) const {
  if (!(wi.z > 0)) return std::nullopt;
  const auto cosineSample = [&]() -> std::optional<Vec3d> {
    const Vec3d wo = sampleCosineHemisphere(u);
    return wo.z > 0 ? std::optional<Vec3d>(wo) : std::nullopt;
  };
  const LobeChoice choice = chooseLobe(uLobe, options_.cosineFraction);
  if (choice.lobe == 0) return cosineSample();
  // The table lobe interpolates two nodes: a second choice with the remapped number.
  const NodeWeights w = nodeWeights(wi.z);
  const bool firstNode = chooseLobe(choice.u, 1.0 - w.secondWeight).lobe == 0;
  const PiecewiseBilinear2D& distribution = nodes_[size_t(firstNode ? w.first : w.second)];
  if (!(distribution.total() > 0)) return cosineSample();

  const Vec2d grid = distribution.sample(u);
  const double oneMinusCos = grid.x;
  const double sinThetaH = safeSqrt(oneMinusCos * (2.0 - oneMinusCos));
  const double hx = sinThetaH * std::cos(grid.y), hy = sinThetaH * std::sin(grid.y);
  const Vec2d azimuth = azimuthOf(wi);  // rotate by +phi_i
  const Vec3d h(hx * azimuth.x - hy * azimuth.y, hx * azimuth.y + hy * azimuth.x, 1.0 - oneMinusCos);
  const Vec3d wo = reflect(wi, h);
  if (!(wo.z > 0)) return std::nullopt;
  return wo;
}

}  // namespace scatterlab
