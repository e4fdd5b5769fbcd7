// The radius distribution of a profile whose cumulative reflectance
//   P(r) = integral_0^r 2 pi r' R(r') dr'
// has a closed form (the dipoles): cdf = P / Rd, pdf = 2 pi r R / Rd, and the inverse by
// tabulated CDF inversion: P tabulated once per channel on a geometric radius grid brackets
// the target, and Newton's method safeguarded by bisection (root_finding.h) solves P(r) = u Rd
// on the exact closed form inside the bracket, to 1e-14 of the radius. So the sampler draws
// exactly the density radiusPdf() states; no table error enters the distribution.
#pragma once

#include <array>
#include <vector>

#include "materials/bssrdf/bssrdf.h"

namespace scatterlab {

class CumulativeProfile : public RadialProfile {
 public:
  Rgb eval(double r) const override {
    return {channelProfile(0, r), channelProfile(1, r), channelProfile(2, r)};
  }
  Rgb totalReflectance() const override { return total_; }
  double radiusCdf(int channel, double r) const override;
  double radiusPdf(int channel, double r) const override;
  double sampleRadius(int channel, double u) const override;

 protected:
  // R(r) and P(r) of one channel.
  virtual double channelProfile(int channel, double r) const = 0;
  virtual double channelCumulative(int channel, double r) const = 0;

  // Call at the end of the derived constructor: the closed-form totals, and per channel a
  // length that sets the scale of the bracketing table (the mean free path 1 / sigma_t').
  void prepareSampling(const Rgb& total, const Rgb& lengthScale);

 private:
  Rgb total_{0.0};
  std::array<std::vector<double>, 3> radii_, cumulative_;
};

}  // namespace scatterlab
