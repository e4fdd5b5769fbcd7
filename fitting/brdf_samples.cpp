#include "fitting/brdf_samples.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "materials/core/rng.h"
#include "materials/measured/half_diff.h"
#include "materials/measured/merl_format.h"

namespace scatterlab::fitting {

void BrdfSamples::reserve(size_t n) {
  wi.reserve(n);
  wo.reserve(n);
  value.reserve(n);
  weight.reserve(n);
  stratum.reserve(n);
}

double BrdfSamples::totalWeight() const { return std::accumulate(weight.begin(), weight.end(), 0.0); }

BrdfSamples samplesFromMerl(const MerlTable& table, MerlSampleCounts* counts) {
  MerlSampleCounts c;
  c.cells = merl::CellCount;
  BrdfSamples samples;
  samples.reserve(merl::CellCount);
  for (int th = 0; th < merl::ThetaHalfCells; ++th) {
    const double thetaHalf = merl::thetaHalfAt(th + 0.5);
    for (int td = 0; td < merl::ThetaDiffCells; ++td) {
      const double thetaDiff = merl::thetaDiffAt(td + 0.5);
      const auto stratum = uint32_t(th * merl::ThetaDiffCells + td);
      for (int pd = 0; pd < merl::PhiDiffCells; ++pd) {
        const size_t cell = merl::cellIndex(th, td, pd);
        if (table.isMissing(cell)) {
          ++c.missing;
          continue;
        }
        const auto [wi, wo] = directionsFromHalfDiff(thetaHalf, 0.0, thetaDiff, merl::phiDiffAt(pd + 0.5));
        if (!(wi.z > 0) || !(wo.z > 0)) {
          ++c.unreachable;
          continue;
        }
        samples.add(wi, wo, table.rgb(cell), 1.0, stratum);
      }
    }
  }
  c.usable = samples.size();
  if (counts) *counts = c;
  return samples;
}

BrdfSamples samplesFromRgl(const RglBrdf& brdf, RglSampleCounts* counts) {
  RglSampleCounts c;
  const auto pairs = brdf.tabulatedPairs(&c.belowHorizon);
  const size_t columns = brdf.colourColumns(), rows = brdf.colourRows();
  BrdfSamples samples;
  samples.reserve(pairs.size());
  for (const RglBrdf::TabulatedPair& pair : pairs)
    samples.add(pair.wi, pair.wo, brdf.eval(pair.wi, pair.wo), 1.0,
                uint32_t(pair.incident * rows + pair.node / columns));
  c.usable = samples.size();
  c.nodes = c.usable + c.belowHorizon;
  if (counts) *counts = c;
  return samples;
}

BrdfSamples stratifiedSubset(const BrdfSamples& samples, size_t target, uint64_t seed) {
  const size_t total = samples.size();
  if (target == 0 || target >= total) return samples;
  BrdfSamples subset;
  subset.reserve(target + total / 64);
  const double fraction = double(target) / double(total);
  std::vector<size_t> order;
  for (size_t begin = 0; begin < total;) {
    const uint32_t stratum = samples.stratum[begin];
    size_t end = begin;
    while (end < total && samples.stratum[end] == stratum) ++end;
    if (end < total && samples.stratum[end] < stratum)
      throw std::invalid_argument("stratifiedSubset: samples are not grouped by increasing stratum");
    const size_t n = end - begin;
    const size_t k = std::min(n, size_t(std::ceil(double(n) * fraction)));
    order.resize(n);
    std::iota(order.begin(), order.end(), begin);
    CounterRng rng(seed, stratum);
    for (size_t i = 0; i < k; ++i) {
      const size_t j = i + std::min(n - i - 1, size_t(rng.uniform() * double(n - i)));
      std::swap(order[i], order[j]);
    }
    // Chosen samples in their original order, so the subset stays grouped and sorted.
    std::sort(order.begin(), order.begin() + std::ptrdiff_t(k));
    const double scale = double(n) / double(k);
    for (size_t i = 0; i < k; ++i) {
      const size_t s = order[i];
      subset.add(samples.wi[s], samples.wo[s], samples.value[s], samples.weight[s] * scale, stratum);
    }
    begin = end;
  }
  return subset;
}

}  // namespace scatterlab::fitting
