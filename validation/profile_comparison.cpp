#include "validation/profile_comparison.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "materials/bssrdf/annulus_profile.h"
#include "materials/core/rng.h"

namespace scatterlab {

namespace {

constexpr ProfileModel Models[] = {ProfileModel::Dipole, ProfileModel::BetterDipole,
                                   ProfileModel::BeamDiffusion, ProfileModel::Burley};

// The power a walk tally puts beyond its last edge, per path.
double walkBeyond(const HalfSpaceWalkResult& walk, bool multipleOnly) {
  uint64_t inside = 0, escaped = walk.escaped;
  for (size_t k = 0; k < walk.counts.size(); ++k)
    inside += walk.counts[k] - (multipleOnly ? walk.singleCounts[k] : 0);
  if (multipleOnly) escaped -= walk.singleEscaped;
  return double(escaped - inside) / double(walk.settings.paths);
}

}  // namespace

const ModelComparison& ProfileComparison::find(ProfileModel model) const {
  for (const ModelComparison& m : models)
    if (m.model == model) return m;
  throw std::out_of_range("profile comparison: model not compared");
}

ProfileComparison compareProfilesWithWalk(const ScatteringMedium& medium,
                                          const ProfileComparisonOptions& options,
                                          const WalkProgress& progress) {
  medium.validate();
  ProfileComparison out;
  out.medium = medium;
  std::vector<std::shared_ptr<const RadialProfile>> profiles;
  double largest = 0.0;
  for (const ProfileModel model : Models) {
    profiles.push_back(makeProfile(model, medium, options.burleyFit));
    for (int c = 0; c < 3; ++c)
      if (profiles.back()->totalReflectance()[c] > 0)
        largest = std::max(largest, profiles.back()->sampleRadius(c, 0.999));
  }
  if (!(largest > 0)) throw std::invalid_argument("profile comparison: no channel reflects");
  out.edges = logRadiusEdges(2e-3 * largest, 2.0 * largest, options.annuli);

  const Rgb albedo = medium.albedo(), extinction = medium.extinction();
  for (int c = 0; c < 3; ++c) {
    HalfSpaceWalkSettings s;
    s.albedo = albedo[c];
    s.extinction = extinction[c];
    s.g = medium.g;
    s.eta = medium.eta;
    s.radiusEdges = out.edges;
    s.paths = options.paths;
    s.seed = deriveSeed(options.seed, uint64_t(c));
    s.threads = options.threads;
    out.walks[size_t(c)] = simulateHalfSpace(
        s, progress ? WalkProgress([&](double f) { progress((c + f) / 3.0); }) : WalkProgress());
    const HalfSpaceWalkResult& w = out.walks[size_t(c)];
    out.walkTotal[c] = w.totalReflectance;
    out.walkStdError[c] = w.totalStdError;
    const double n = double(w.settings.paths), multiple = double(w.escaped - w.singleEscaped) / n;
    out.walkMultipleTotal[c] = multiple;
    out.walkMultipleStdError[c] = std::sqrt(multiple * (1.0 - multiple) / n);
    out.noiseFloor[c] = radialNoiseFloor(out.edges, w.profile, n);
  }

  for (size_t m = 0; m < profiles.size(); ++m) {
    const RadialProfile& profile = *profiles[m];
    ModelComparison comparison{Models[m], {}};
    ProfileErrors& e = comparison.errors;
    e.total = profile.totalReflectance();
    for (int c = 0; c < 3; ++c) {
      const HalfSpaceWalkResult& w = out.walks[size_t(c)];
      const std::vector<double> means = annulusMeans(profile, c, out.edges);
      const double beyond =
          e.total[c] > 0 ? e.total[c] * (1.0 - profile.radiusCdf(c, out.edges.back())) : 0.0;
      const auto relative = [](double model, double reference) {
        return reference > 0 ? model / reference - 1.0 : 0.0;
      };
      e.totalError[c] = relative(e.total[c], out.walkTotal[c]);
      e.multipleTotalError[c] = relative(e.total[c], out.walkMultipleTotal[c]);
      e.profileError[c] = radialRelativeError(out.edges, means, w.profile, beyond, walkBeyond(w, false));
      e.multipleProfileError[c] =
          radialRelativeError(out.edges, means, w.multipleScatteringProfile(), beyond, walkBeyond(w, true));
    }
    out.models.push_back(comparison);
  }
  return out;
}

}  // namespace scatterlab
