#include "materials/bssrdf/annulus_profile.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace scatterlab {

std::vector<double> annulusAreas(std::span<const double> edges) {
  std::vector<double> areas;
  for (size_t k = 0; k + 1 < edges.size(); ++k) areas.push_back(Pi * (sqr(edges[k + 1]) - sqr(edges[k])));
  return areas;
}

std::vector<double> annulusMeans(const RadialProfile& profile, int channel, std::span<const double> edges) {
  const double total = profile.totalReflectance()[channel];
  const std::vector<double> areas = annulusAreas(edges);
  std::vector<double> means;
  for (size_t k = 0; k < areas.size(); ++k) {
    const double mass =
        total > 0 ? total * (profile.radiusCdf(channel, edges[k + 1]) - profile.radiusCdf(channel, edges[k]))
                  : 0.0;
    means.push_back(mass / areas[k]);
  }
  return means;
}

double radialRelativeError(std::span<const double> edges, std::span<const double> model,
                           std::span<const double> reference, double modelBeyond, double referenceBeyond) {
  const std::vector<double> areas = annulusAreas(edges);
  if (model.size() != areas.size() || reference.size() != areas.size())
    throw std::invalid_argument("radialRelativeError: one value per annulus needed");
  double difference = std::abs(modelBeyond - referenceBeyond), total = referenceBeyond;
  for (size_t k = 0; k < areas.size(); ++k) {
    difference += std::abs(model[k] - reference[k]) * areas[k];
    total += reference[k] * areas[k];
  }
  return total > 0 ? difference / total : 0.0;
}

std::vector<size_t> logAnnulusGroups(std::span<const double> edges, int groups) {
  if (edges.size() < 3 || groups < 2)
    throw std::invalid_argument("logAnnulusGroups: need two annuli and two groups");
  const double first = edges[1], last = edges.back();
  std::vector<size_t> out{0};
  for (int g = 0; g < groups; ++g) {
    const double target = first * std::pow(last / first, double(g) / double(groups - 1));
    size_t best = 1;
    for (size_t k = 1; k < edges.size(); ++k)
      if (std::abs(edges[k] - target) < std::abs(edges[best] - target)) best = k;
    if (best > out.back()) out.push_back(best);
  }
  if (out.back() != edges.size() - 1) out.push_back(edges.size() - 1);
  return out;
}

std::vector<double> groupedEdges(std::span<const double> edges, std::span<const size_t> groups) {
  std::vector<double> out;
  for (const size_t g : groups) out.push_back(edges[g]);
  return out;
}

std::vector<double> groupedMeans(std::span<const double> edges, std::span<const double> means,
                                 std::span<const size_t> groups) {
  const std::vector<double> areas = annulusAreas(edges);
  std::vector<double> out;
  for (size_t g = 0; g + 1 < groups.size(); ++g) {
    double power = 0.0, area = 0.0;
    for (size_t k = groups[g]; k < groups[g + 1]; ++k) {
      power += means[k] * areas[k];
      area += areas[k];
    }
    out.push_back(power / area);
  }
  return out;
}

double radialNoiseFloor(std::span<const double> edges, std::span<const double> reference, double paths) {
  const std::vector<double> areas = annulusAreas(edges);
  double deviation = 0.0, total = 0.0;
  for (size_t k = 0; k < areas.size(); ++k) {
    const double p = reference[k] * areas[k];
    deviation += std::sqrt(2.0 / Pi) * std::sqrt(std::max(0.0, p * (1.0 - p)) / paths);
    total += p;
  }
  return total > 0 ? deviation / total : 0.0;
}

}  // namespace scatterlab
