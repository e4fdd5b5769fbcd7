#include <gtest/gtest.h>

#include "materials/bssrdf/burley.h"
#include "materials/bssrdf/probe_sampling.h"
#include "materials/core/quadrature.h"
#include "materials/core/rng.h"

namespace scatterlab {
namespace probe_sampling_test {

const BurleyProfile& colouredProfile() {
  static const BurleyProfile p(Rgb(0.8, 0.5, 0.2), Rgb(0.5, 1.0, 2.0));
  return p;
}

TEST(ProbeSampler, ChordsPassThroughTheDiskPointWithinTheSphere) {
  const ProbeSampler sampler(colouredProfile());
  const Framed frame = Framed::fromNormal(glm::normalize(Vec3d(0.2, -0.1, 1.0)));
  const Vec3d origin(1.0, 2.0, 3.0);
  CounterRng rng(5, 0);
  for (int i = 0; i < 1000; ++i) {
    const double uChoice = rng.uniform();
    const Vec2d u = rng.uniform2D();
    const ProbeSegment s = sampler.sample(frame, origin, uChoice, u);
    const double rMax = sampler.maxRadius(s.channel);
    EXPECT_LE(s.radius, rMax);
    EXPECT_NEAR(glm::length(s.start - origin), rMax, 1e-9 * rMax);  // chord ends on the sphere
    EXPECT_NEAR(glm::length(s.end - origin), rMax, 1e-9 * rMax);
    const Vec3d axis = s.axis == 0 ? frame.n : (s.axis == 1 ? frame.s : frame.t);
    const Vec3d mid = 0.5 * (s.start + s.end) - origin;
    EXPECT_NEAR(glm::dot(mid, axis), 0.0, 1e-12);  // the chord's middle is on the disk
    EXPECT_NEAR(glm::length(mid), s.radius, 1e-12 + 1e-12 * s.radius);
    EXPECT_NEAR(glm::length(glm::cross(s.end - s.start, axis)), 0.0, 1e-9 * rMax);  // parallel to the axis
  }
}

TEST(ProbeSampler, AxisAndChannelFrequenciesFollowTheirProbabilities) {
  const ProbeSampler sampler(colouredProfile());
  int axis[3] = {0, 0, 0}, channel[3] = {0, 0, 0};
  const int n = 30000;
  for (int i = 0; i < n; ++i) {
    const ProbeSegment s = sampler.sample(Framed(), Vec3d(0.0), (i + 0.5) / n, {0.5, 0.5});
    ++axis[s.axis];
    ++channel[s.channel];
  }
  // Stratified uChoice: the counts are exact up to one per cell boundary.
  EXPECT_NEAR(axis[0], n / 2, 2);
  EXPECT_NEAR(axis[1], n / 4, 2);
  EXPECT_NEAR(channel[0], n / 3, 3);
  EXPECT_NEAR(channel[2], n / 3, 3);
}

TEST(ProbeSampler, AlignedFramePdfIntegratesToTheNormalAxisShareOverThePlane) {
  // With the frame's normal = the plane's, tangent chords run parallel to the plane and find
  // nothing: the density integrates to P(normal axis) = 0.5.
  const ProbeSampler sampler(colouredProfile());
  QuadratureOptions q;
  q.relativeTolerance = 1e-9;
  q.minDepth = 5;
  double total = 0.0;
  // Integrate ring by ring in ln rho, breaking at every r_max (the density jumps there).
  std::vector<double> edges{1e-12, sampler.maxRadius(0), sampler.maxRadius(1), sampler.maxRadius(2)};
  std::sort(edges.begin(), edges.end());
  for (size_t k = 0; k + 1 < edges.size(); ++k)
    total += adaptiveSimpson2D(
        [&](double t, double phi) {
          const double rho = std::exp(t);
          return sampler.pdf(Framed(), Vec3d(0.0), Vec3d(rho * std::cos(phi), rho * std::sin(phi), 0.0),
                             Vec3d(0, 0, 1)) *
                 rho * rho;
        },
        std::log(edges[k]) + 1e-12, std::log(edges[k + 1]) - 1e-12, -Pi, Pi, q);
  EXPECT_NEAR(total, 0.5, 1e-6);
}

TEST(ProbeSampler, DensityVanishesBeyondTheLargestSphere) {
  const ProbeSampler sampler(colouredProfile());
  const double beyond = 1.0001 * sampler.largestRadius();
  EXPECT_EQ(sampler.pdf(Framed(), Vec3d(0.0), Vec3d(beyond, 0, 0), Vec3d(0, 0, 1)), 0.0);
  EXPECT_GT(sampler.pdf(Framed(), Vec3d(0.0), Vec3d(0.5 * beyond, 0, 0), Vec3d(0, 0, 1)), 0.0);
}

TEST(ProbeSampler, DefaultChannelProbabilitiesSkipChannelsThatReflectNothing) {
  const BurleyProfile p(Rgb(0.8, 0.0, 0.2), Rgb(1.0));
  const ProbeSampling s = defaultProbeSampling(p);
  EXPECT_DOUBLE_EQ(s.channelProbability[0], 0.5);
  EXPECT_EQ(s.channelProbability[1], 0.0);
  ProbeSampling bad;
  bad.axisProbability = {0.5, 0.5, 0.5};
  EXPECT_THROW(ProbeSampler(p, bad), std::invalid_argument);
}

}  // namespace probe_sampling_test
}  // namespace scatterlab
