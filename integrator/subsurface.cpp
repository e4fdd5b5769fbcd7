#include "integrator/subsurface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "integrator/sample_value.h"
#include "integrator/scene.h"
#include "materials/bsdf/dielectric_index_spec.h"
#include "materials/bsdf/rough_dielectric.h"
#include "materials/bsdf/smooth_dielectric.h"
#include "materials/bssrdf/henyey_greenstein.h"
#include "materials/core/lobe_choice.h"

namespace scatterlab {

namespace {

// A chord of a closed analytic shape crosses it twice at most; a plane once.
constexpr int MaxProbeCrossings = 8;

double sumOf(const Rgb& v) { return v.x + v.y + v.z; }

Rgb exponential(const Rgb& v) { return Rgb(std::exp(v.x), std::exp(v.y), std::exp(v.z)); }

}  // namespace

std::vector<std::string> subsurfaceModeNames() { return {"diffusion", "walk"}; }

std::optional<SubsurfaceMode> findSubsurfaceMode(const std::string& name) {
  if (name == "diffusion") return SubsurfaceMode::Diffusion;
  if (name == "walk") return SubsurfaceMode::RandomWalk;
  return std::nullopt;
}

std::string toString(SubsurfaceMode mode) { return mode == SubsurfaceMode::Diffusion ? "diffusion" : "walk"; }

std::unique_ptr<BsdfModel> makeSubsurfaceBoundary(const SubsurfaceMaterial& material) {
  const double eta = material.medium.eta;
  if (material.boundary == SubsurfaceBoundary::Smooth) return std::make_unique<SmoothDielectricBsdf>(eta);
  // The registry refuses such a material when it is read (subsurface_registry.cpp); a
  // SubsurfaceMaterial built in code reaches here unchecked.
  if (!RoughDielectricIndexRange.contains(eta))
    throw std::invalid_argument("subsurface material: a rough boundary needs eta " +
                                RoughDielectricIndexRange.describe() + ", not " + std::to_string(eta) +
                                " (use \"boundary\": \"smooth\")");
  return makeRoughDielectric(MicrofacetType::Ggx, material.roughness, material.roughness, eta,
                             MultipleScattering::KullaConty);
}

SceneSubsurface::SceneSubsurface(const SubsurfaceMaterial& m, SubsurfaceMode walkMode,
                                 const BsdfModel& boundaryModel)
    : material(m),
      mode(walkMode),
      boundary(&boundaryModel),
      probe(*material.profile),
      exit(material.medium.eta),
      sigmaS(material.medium.sigmaS),
      sigmaT(material.medium.sigmaS + material.medium.sigmaA) {}

std::optional<DiffusionExit> sampleDiffusionExit(const Scene& scene, int shape,
                                                 const SceneSubsurface& subsurface, const Vec3d& point,
                                                 const Vec3d& normal, SampleStream& random) {
  const Framed frame = Framed::fromNormal(normal);
  const double uChoice = random.next();
  const ProbeSegment segment = subsurface.probe.sample(frame, point, uChoice, random.next2D());
  const Vec3d chord = segment.end - segment.start;
  const double length = glm::length(chord);
  if (!(length > 0)) return std::nullopt;
  const Ray ray{segment.start, chord / length};
  // Every crossing of the chord with the shape; successive searches start just past the last
  // one (the relative offset of ray.h).
  const double step =
      RayOffsetScale * std::max({1.0, length, std::abs(point.x), std::abs(point.y), std::abs(point.z)});
  std::array<double, MaxProbeCrossings> crossings{};
  int count = 0;
  for (double tMin = 0.0; count < MaxProbeCrossings;) {
    const double t = scene.intersectShape(shape, ray, tMin, length);
    if (t == Infinity) break;
    crossings[size_t(count++)] = t;
    tMin = t + step;
  }
  if (count == 0) return std::nullopt;
  const int chosen = std::min(int(random.next() * count), count - 1);
  const Vec3d xo = ray.at(crossings[size_t(chosen)]);
  const SurfaceGeometry geometry = scene.shapeGeometry(shape, xo);
  const double pdf = subsurface.probe.pdf(frame, point, xo, geometry.normal) / count;
  if (!(pdf > 0)) return std::nullopt;
  // A weight that is not finite or negative is returned as it is: the path tracer ends the path
  // on it and the film counts the sample (sample_value.h), where dropping it here would hide it.
  const Rgb weight = subsurface.material.profile->eval(glm::length(xo - point)) / pdf;
  return DiffusionExit{xo, geometry, weight};
}

std::optional<WalkExit> walkThroughMedium(const Scene& scene, int shape, const SceneSubsurface& subsurface,
                                          const Ray& inward, SampleStream& random) {
  const Rgb& sigmaT = subsurface.sigmaT;
  Rgb weight(1.0);
  Vec3d p = inward.origin, d = inward.direction;
  for (int event = 0; event < MaxWalkEvents; ++event) {
    if (!(weight.x + weight.y + weight.z > 0)) return std::nullopt;  // every channel absorbed
    const double boundary = scene.intersectShape(shape, Ray{p, d}, 0.0, Infinity);
    if (boundary == Infinity) return std::nullopt;  // outside a shape that is not closed
    // The channel of this flight, with probabilities proportional to the walk's weights.
    const Rgb channelProbability = weight / (weight.x + weight.y + weight.z);
    const std::array<double, 3> probabilities{channelProbability.x, channelProbability.y,
                                              channelProbability.z};
    const int channel = chooseLobe(random.next(), probabilities).lobe;  // weight > 0: never -1
    const double flight = sigmaT[channel] > 0 ? -std::log1p(-random.next()) / sigmaT[channel] : Infinity;
    if (flight < boundary) {
      // A collision: sigma_s,k T_k(t) over the mixture density of the three flights.
      const Rgb transmittance = exponential(-sigmaT * flight);
      weight *= subsurface.sigmaS * transmittance / sumOf(channelProbability * sigmaT * transmittance);
      p += flight * d;
      d = sampleHenyeyGreenstein(d, subsurface.material.medium.g, random.next2D());
    } else {
      // The boundary: T_k(t) over the mixture probability of flying that far, then the
      // dielectric from inside.
      const Rgb transmittance = exponential(-sigmaT * boundary);
      weight *= transmittance / sumOf(channelProbability * transmittance);
      const Vec3d hit = p + boundary * d;
      const SurfaceGeometry geometry = scene.shapeGeometry(shape, hit);
      const Bsdf interface(*subsurface.boundary, Framed::fromNormal(geometry.normal), false);
      const double uLobe = random.next();
      const std::optional<BsdfSample> sample =
          interface.sample(-d, uLobe, random.next2D(), TransportMode::Radiance);
      if (!sample || sample->weight == Rgb(0.0)) return std::nullopt;
      weight *= sample->weight;
      if (hasAny(sample->lobe, LobeFlags::Transmission))
        return WalkExit{hit, geometry.normal, sample->wo, weight};
      d = sample->wo;
      p = offsetRayOrigin(hit, geometry.normal, d);
    }
    // A weight that is not finite or negative leaves the walk as it is, where it arose (before
    // the roulette could end the walk on it): the path tracer ends the path on it and the film
    // counts the sample (sample_value.h).
    if (classifyValue(weight) != SampleValue::Valid) return WalkExit{p, -d, d, weight};
    // Russian roulette on the walk's own weight (path_tracer.cpp does the same for the path).
    if (event >= WalkRouletteEvents) {
      const double q = std::max({weight.x, weight.y, weight.z});
      if (q < 1.0) {
        if (random.next() >= q) return std::nullopt;
        weight /= q;
      }
    }
  }
  return std::nullopt;
}

bool entersMedium(const SurfaceInteraction& hit, const Vec3d& wi, const BsdfSample& sample) {
  return hit.subsurface && hasAny(sample.lobe, LobeFlags::Transmission) &&
         glm::dot(wi, hit.geometry.normal) > 0;
}

std::optional<MediumExit> leaveMedium(const Scene& scene, const SurfaceInteraction& hit,
                                      const BsdfSample& sample, SampleStream& random) {
  const SceneSubsurface& medium = *hit.subsurface;
  if (medium.mode == SubsurfaceMode::RandomWalk) {
    // The radiance scalings of entering and leaving cancel.
    const std::optional<WalkExit> exit = walkThroughMedium(
        scene, hit.shape, medium, spawnRay(hit.point, hit.geometry.normal, sample.wo), random);
    if (!exit) return std::nullopt;
    return MediumExit{sample.weight * exit->weight, std::nullopt,
                      spawnRay(exit->point, exit->normal, exit->direction)};
  }
  // The BSSRDF: Ft(wo) without the radiance scaling, R / pdf to the probe's point, and there a
  // vertex of the directional term Sw.
  const std::optional<DiffusionExit> exit =
      sampleDiffusionExit(scene, hit.shape, medium, hit.point, hit.geometry.normal, random);
  if (!exit) return std::nullopt;
  SurfaceInteraction vertex;
  vertex.point = exit->point;
  vertex.geometry = exit->geometry;
  vertex.model = &medium.exit;
  vertex.shape = hit.shape;
  return MediumExit{sample.weight * (sample.eta * sample.eta) * exit->weight, vertex, Ray{}};
}

}  // namespace scatterlab
