#include "materials/bssrdf/probe_sampling.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "materials/core/lobe_choice.h"

namespace scatterlab {

namespace {

void checkProbabilities(const std::array<double, 3>& p, const char* what) {
  double sum = 0;
  for (double x : p) {
    if (!(x >= 0) || !std::isfinite(x))
      throw std::invalid_argument(std::string("probe sampling: negative ") + what);
    sum += x;
  }
  if (std::abs(sum - 1.0) > 1e-12)
    throw std::invalid_argument(std::string("probe sampling: ") + what + " do not sum to 1");
}

Vec3d axisOf(const Framed& frame, int axis) { return axis == 0 ? frame.n : (axis == 1 ? frame.s : frame.t); }

}  // namespace

ProbeSampling defaultProbeSampling(const RadialProfile& profile) {
  ProbeSampling sampling;
  const Rgb total = profile.totalReflectance();
  int reflecting = 0;
  for (int c = 0; c < 3; ++c) reflecting += total[c] > 0 ? 1 : 0;
  for (int c = 0; c < 3; ++c) sampling.channelProbability[c] = total[c] > 0 ? 1.0 / reflecting : 0.0;
  if (reflecting == 0) sampling.channelProbability = {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
  return sampling;
}

ProbeSampler::ProbeSampler(const RadialProfile& profile)
    : ProbeSampler(profile, defaultProbeSampling(profile)) {}

ProbeSampler::ProbeSampler(const RadialProfile& profile, const ProbeSampling& sampling)
    : profile_(&profile), sampling_(sampling) {
  checkProbabilities(sampling.axisProbability, "axis probabilities");
  checkProbabilities(sampling.channelProbability, "channel probabilities");
  if (!(sampling.truncation > 0 && sampling.truncation <= 1))
    throw std::invalid_argument("probe sampling: the truncation must be in (0, 1]");
  for (int c = 0; c < 3; ++c)
    maxRadius_[c] = sampling.channelProbability[c] > 0 ? profile.sampleRadius(c, sampling.truncation) : 0.0;
}

double ProbeSampler::largestRadius() const { return *std::max_element(maxRadius_.begin(), maxRadius_.end()); }

ProbeSegment ProbeSampler::sample(const Framed& frame, const Vec3d& origin, double uChoice,
                                  const Vec2d& u) const {
  // The constructor checked that both sets of probabilities sum to 1: lobe is never -1.
  const auto [axis, uChannel] = chooseLobe(uChoice, sampling_.axisProbability);
  const int channel = chooseLobe(uChannel, sampling_.channelProbability).lobe;
  const double r = profile_->sampleRadius(channel, u.x * sampling_.truncation);
  const double phi = 2.0 * Pi * u.y;
  const Vec3d a = axisOf(frame, axis), b1 = axisOf(frame, (axis + 1) % 3), b2 = axisOf(frame, (axis + 2) % 3);
  const double rMax = maxRadius_[channel];
  const double halfChord = safeSqrt(rMax * rMax - r * r);
  const Vec3d onDisk = origin + r * (std::cos(phi) * b1 + std::sin(phi) * b2);
  return {onDisk + halfChord * a, onDisk - halfChord * a, axis, channel, r};
}

double ProbeSampler::diskDensity(int channel, double r) const {
  if (!(r > 0) || !(r < maxRadius_[channel])) return 0.0;
  return profile_->radiusPdf(channel, r) / (sampling_.truncation * 2.0 * Pi * r);
}

double ProbeSampler::pdf(const Framed& frame, const Vec3d& origin, const Vec3d& xo,
                         const Vec3d& normalAtExit) const {
  const Vec3d d = xo - origin;
  const double distance2 = glm::dot(d, d);
  double total = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double pAxis = sampling_.axisProbability[axis];
    if (!(pAxis > 0)) continue;
    const Vec3d a = axisOf(frame, axis);
    const double along = glm::dot(d, a);
    const double projected = safeSqrt(distance2 - along * along);
    const double cosine = std::abs(glm::dot(normalAtExit, a));
    double channels = 0.0;
    for (int c = 0; c < 3; ++c)
      if (sampling_.channelProbability[c] > 0 && distance2 < maxRadius_[c] * maxRadius_[c])
        channels += sampling_.channelProbability[c] * diskDensity(c, projected);
    total += pAxis * cosine * channels;
  }
  return total;
}

}  // namespace scatterlab
