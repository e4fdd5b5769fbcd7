// Where light paths start (light tracing, BDPT's light subpaths, SPPM's photons): a light
// chosen in proportion to the power it sends into the scene, then a ray leaving it, with the
// densities BDPT's multiple importance sampling needs to weigh the strategies that start there.
//
// A sphere light sends a ray from a point uniform on its area (density 1 / (4 pi r^2)) in a
// cosine-distributed direction about the normal (cos / pi): weight Le pi 4 pi r^2 / P(light).
//
// Light from infinity (the environment, a sun) arrives along a direction d from the light's own
// sampler, through a point of the plane perpendicular to d through the centre c of the scene's
// finite shapes (Scene::finiteBounds, radius R). The point's distance rho from c has the
// density, per unit area of that plane,
//   p(rho) = R / (2 pi (R^2 + rho^2)^(3/2)),   sampled as rho = R sqrt(1 / (1 - u)^2 - 1),
// positive everywhere: the preview scene's ground is an infinite plane, and a disk of any
// radius would leave the ground beyond it unlit by particles, so light tracing would be biased.
// The tail rho^-3 keeps the variance finite: a patch of lit ground at distance r adds ~ r^-3 to
// a pixel of the sphere (its solid angle and slant), and with a density ~ r^-3 the second
// moment integrates r^-6 / r^-3 r dr, which converges. The price: at the centre the density is
// half that of the uniform disk of radius R (pbrt-v4's choice for bounded scenes), at rho = R a
// sixth of it; 29% of the rays pass within R.
#pragma once

#include <optional>
#include <vector>

#include "integrator/sampler.h"
#include "integrator/scene.h"

namespace scatterlab {

struct EmittedRay {
  Ray ray;
  Rgb weight;                   // Le |cos| / (pdfLight pdfNext): the path's starting throughput
  int light;                    // index into Scene::lights(LightSet::All)
  bool atInfinity = false;      // environment or sun: the path's first vertex is a direction
  bool deltaDirection = false;  // a delta sun
  Vec3d normal{0.0};            // sphere light: the normal at the ray's origin
  // The densities of the ray, split as BDPT's path vertices need them. pdfLight: of the light's
  // vertex, P(light) included: per unit area of a sphere light; per unit solid angle of the
  // direction for light at infinity (1 for a delta sun). pdfNext: of what comes next: the
  // direction leaving a sphere light, per unit solid angle (cos / pi); the line's point on the
  // perpendicular plane, per unit area, for light at infinity.
  double pdfLight = 0.0, pdfNext = 0.0;
};

class LightEmission {
 public:
  explicit LightEmission(const Scene& scene);

  // False when no light sends anything.
  bool hasLight() const { return total_ > 0; }
  // Four random numbers; nothing when the chosen light cannot send this sample.
  std::optional<EmittedRay> sample(SampleStream& random) const;

  // The probability of choosing light `light` (index into Scene::lights()).
  double selectionProbability(int light) const { return probability_[size_t(light)]; }
  // Sphere light: the density per unit area of a ray's origin on it, P(light) included.
  double spherePositionPdf(int light) const;
  // Sphere light: the density per unit solid angle of leaving its surface point with normal
  // n along w (cos / pi).
  static double sphereDirectionPdf(const Vec3d& n, const Vec3d& w) {
    const double c = glm::dot(n, w);
    return c > 0 ? c * InvPi : 0.0;
  }
  // Light at infinity: P(light) times the density of sending light along `travel` (the
  // direction the light moves in); for a delta sun, P(light) along its own direction.
  double infiniteDirectionPdf(int light, const Vec3d& travel) const;
  // Light at infinity moving along `travel`: the density per unit area, on the plane
  // perpendicular to it, of the line through `point`.
  double perpendicularPdf(const Vec3d& point, const Vec3d& travel) const;

 private:
  const Scene* scene_;
  Sphere bounds_;
  std::vector<double> probability_, cumulative_;
  double total_ = 0.0;
};

}  // namespace scatterlab
