#include "materials/bssrdf/beam_diffusion_table.h"

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <utility>

#include "materials/bssrdf/photon_beam_diffusion.h"
#include "materials/core/catmull_rom.h"
#include "materials/core/gauss_legendre.h"
#include "materials/core/root_finding.h"

namespace scatterlab {

namespace {

// 2 pi r (MS + SS)(r) at optical radius r > 0.
double profileDensity(double rho, double g, double eta, const FresnelBoundary& boundary, double r) {
  return 2.0 * Pi * r * (beamDiffusionMultiple(rho, g, boundary, r) + beamDiffusionSingle(rho, g, eta, r));
}

}  // namespace

BeamDiffusionTable::BeamDiffusionTable(double g, double eta) : g_(g), eta_(eta) {
  if (!(g > -1 && g < 1)) throw std::invalid_argument("beam diffusion table: g must be in (-1, 1)");
  if (!(eta > 0) || !std::isfinite(eta))
    throw std::invalid_argument("beam diffusion table: eta must be positive");
  for (int i = 0; i < AlbedoCount; ++i)
    albedos_[i] = (1.0 - std::exp(-8.0 * i / (AlbedoCount - 1))) / (1.0 - std::exp(-8.0));
  radii_[0] = 0.0;
  radii_[1] = 2.5e-3;
  for (int j = 2; j < RadiusCount; ++j) radii_[j] = 1.2 * radii_[j - 1];

  const FresnelBoundary boundary = fresnelBoundary(eta);
  cumulative_.resize(AlbedoCount);
  density_.resize(AlbedoCount);
  // Each interval [r_(j-1), r_j] by 6-point Gauss-Legendre: the profile is smooth on these
  // geometric steps (ratio 1.2), and at [0, r_1] varies as r ln r at worst.
  const GaussLegendreRule<6>& rule = gaussLegendre<6>();
  // Serial: a table costs ~0.3 s of CPU once per (g, eta) and process (shared() caches it).
  for (int i = 0; i < AlbedoCount; ++i) {
    const double rho = albedos_[i];
    auto& P = cumulative_[i];
    auto& f = density_[i];
    f[0] = 2.0 * Pi * beamDiffusionSingleLimit(rho, g, eta);  // r MS(r) -> 0; r SS(r) -> its limit
    P[0] = 0.0;
    for (int j = 1; j < RadiusCount; ++j) {
      const double lo = radii_[j - 1], width = radii_[j] - lo;
      double mass = 0.0;
      for (int k = 0; k < 6; ++k)
        mass += rule.weights[k] * profileDensity(rho, g, eta, boundary, lo + rule.nodes[k] * width);
      P[j] = P[j - 1] + mass * width;
      f[j] = profileDensity(rho, g, eta, boundary, radii_[j]);
    }
  }
}

std::shared_ptr<const BeamDiffusionTable> BeamDiffusionTable::shared(double g, double eta) {
  static std::mutex mutex;
  static std::map<std::pair<double, double>, std::shared_ptr<const BeamDiffusionTable>> cache;
  const std::lock_guard lock(mutex);
  auto& entry = cache[{g, eta}];
  if (!entry) entry = std::make_shared<const BeamDiffusionTable>(g, eta);
  return entry;
}

MonotoneCubicCdf BeamDiffusionTable::profileAt(double rho) const {
  const CatmullRomWeights w = catmullRomWeights(albedos_, std::clamp(rho, 0.0, 1.0));
  std::vector<double> x(radii_.begin(), radii_.end()), P(RadiusCount, 0.0), f(RadiusCount, 0.0);
  for (int k = 0; k < 4; ++k) {
    const int row = w.offset + k;
    if (row < 0 || row >= AlbedoCount || w.weight[k] == 0.0) continue;
    for (int j = 0; j < RadiusCount; ++j) {
      P[j] += w.weight[k] * cumulative_[row][j];
      f[j] += w.weight[k] * density_[row][j];
    }
  }
  P[0] = 0.0;
  for (int j = 0; j < RadiusCount; ++j) {
    if (j > 0) P[j] = std::max(P[j], P[j - 1]);
    f[j] = std::max(f[j], 0.0);
  }
  return MonotoneCubicCdf(std::move(x), std::move(P), std::move(f));
}

double BeamDiffusionTable::albedoForEffectiveAlbedo(double rhoEff) const {
  return bisectIncreasing([&](double rho) { return effectiveAlbedo(rho); }, rhoEff, 0.0, 1.0, 1e-12);
}

}  // namespace scatterlab
