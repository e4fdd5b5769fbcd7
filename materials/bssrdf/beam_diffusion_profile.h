// The photon beam diffusion profile of a medium (beam_diffusion_table.h), per channel: the
// table's radius CDF at the channel's albedo rho = sigma_s / sigma_t, scaled from optical to
// physical radius by sigma_t: P(r) = P_opt(sigma_t r), R(r) = sigma_t^2 P_opt'(sigma_t r) /
// (2 pi sigma_t r). The profile is zero beyond 203 mean free paths (the table's last radius),
// its total reflectance is the table's effective albedo, and the radius sampler inverts the
// same cubic CDF, so eval, cdf, pdf and sample describe one distribution exactly.
#pragma once

#include <array>
#include <memory>

#include "materials/bssrdf/beam_diffusion_table.h"
#include "materials/bssrdf/bssrdf.h"
#include "materials/bssrdf/medium.h"

namespace scatterlab {

class BeamDiffusionProfile final : public RadialProfile {
 public:
  // The medium's sigma_s, sigma_a, g and eta (validated: medium.h).
  explicit BeamDiffusionProfile(const ScatteringMedium& medium);

  std::string name() const override { return "beam-diffusion"; }
  Rgb eval(double r) const override;
  Rgb totalReflectance() const override { return total_; }
  double radiusCdf(int channel, double r) const override;
  double radiusPdf(int channel, double r) const override;
  double sampleRadius(int channel, double u) const override;

  const BeamDiffusionTable& table() const { return *table_; }

 private:
  std::shared_ptr<const BeamDiffusionTable> table_;
  Rgb sigmaT_{0.0}, total_{0.0};
  std::array<MonotoneCubicCdf, 3> cdf_;  // optical radius
};

}  // namespace scatterlab
