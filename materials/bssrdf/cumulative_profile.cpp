#include "materials/bssrdf/cumulative_profile.h"

#include <algorithm>
#include <cmath>

#include "materials/core/root_finding.h"

namespace scatterlab {

namespace {
// The bracketing table: 8 radii per decade from 1e-6 to 1e6 mean free paths, which holds all
// but ~1e-6 of every profile's mass (beyond, the bracket grows by doubling).
constexpr double TableLow = 1e-6, TableHigh = 1e6;
constexpr int PerDecade = 8;
}  // namespace

void CumulativeProfile::prepareSampling(const Rgb& total, const Rgb& lengthScale) {
  total_ = total;
  const int count = int(std::lround(std::log10(TableHigh / TableLow) * PerDecade)) + 1;
  for (int c = 0; c < 3; ++c) {
    radii_[c].clear();
    cumulative_[c].clear();
    for (int k = 0; k < count; ++k) {
      const double r = lengthScale[c] * TableLow * std::pow(10.0, double(k) / PerDecade);
      radii_[c].push_back(r);
      cumulative_[c].push_back(channelCumulative(c, r));
    }
  }
}

double CumulativeProfile::radiusCdf(int channel, double r) const {
  if (!(r > 0) || !(total_[channel] > 0)) return 0.0;
  return std::clamp(channelCumulative(channel, r) / total_[channel], 0.0, 1.0);
}

double CumulativeProfile::radiusPdf(int channel, double r) const {
  if (!(r >= 0) || !(total_[channel] > 0)) return 0.0;
  return 2.0 * Pi * r * channelProfile(channel, r) / total_[channel];
}

double CumulativeProfile::sampleRadius(int channel, double u) const {
  const double target = u * total_[channel];
  if (!(target > 0)) return 0.0;
  const std::vector<double>& radii = radii_[channel];
  const std::vector<double>& cumulative = cumulative_[channel];
  const size_t k =
      size_t(std::lower_bound(cumulative.begin(), cumulative.end(), target) - cumulative.begin());
  double lo = k == 0 ? 0.0 : radii[k - 1], hi;
  double pLo = k == 0 ? 0.0 : cumulative[k - 1], pHi;
  if (k < radii.size()) {
    hi = radii[k];
    pHi = cumulative[k];
  } else {
    // Heavier tails than the table (no absorption: R ~ r^-3): double until bracketed.
    hi = radii.back();
    pHi = cumulative.back();
    while (pHi < target && hi < 1e300) {
      lo = hi;
      pLo = pHi;
      hi *= 2.0;
      pHi = channelCumulative(channel, hi);
    }
  }
  const double guess = pHi > pLo ? lo + (hi - lo) * (target - pLo) / (pHi - pLo) : 0.5 * (lo + hi);
  return solveIncreasing(
      [&](double r) {
        return ValueAndSlope{channelCumulative(channel, r), 2.0 * Pi * r * channelProfile(channel, r)};
      },
      target, lo, hi, guess, 1e-14 * hi);
}

}  // namespace scatterlab
