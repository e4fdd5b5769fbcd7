// Subpaths: the random walks that light tracing, BDPT and SPPM's photons are made of (Veach
// 1997, ch. 10.2). A camera subpath starts at the eye and carries radiance (BSDFs sampled with
// TransportMode::Radiance); a light subpath starts on a light (emission.h) and carries
// importance (TransportMode::Importance: no 1/eta^2 at refractions, Veach 1997 sec. 5.2).
//
// Every vertex keeps what BDPT's multiple importance sampling needs to weigh the strategies
// that could have made a path through it: the density with which its own subpath reached it
// (pdfForward) and the density with which a subpath from the other end would have
// (pdfReverse), both per unit area of the surface (for a light at infinity, per unit solid
// angle of its direction), and whether the vertex scattered by a delta lobe. A density of
// sampling out of a delta vertex is taken as 1 in both directions and not converted to area:
// it is the same whichever end made the path, which is all the weights need (each strategy's
// weight is then one function of the path, and they sum to 1).
//
// Russian roulette from `rouletteDepth` bounces on, as in the path tracer: a camera subpath on
// its throughput times the refractions' etaRel^2 (path_tracer.h), a light subpath on its
// throughput relative to what it started with.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "integrator/emission.h"
#include "integrator/pixel_filter.h"
#include "integrator/sample_value.h"
#include "integrator/sampler.h"
#include "integrator/scene.h"

namespace scatterlab {

struct PathVertex {
  enum class Kind : uint8_t { Eye, Light, Surface };
  Kind kind = Kind::Surface;
  // Eye: hit.point is the eye. Light: on a sphere light, hit.point and hit.geometry.normal;
  // at infinity, `direction` is the way the light travels. Surface: where the subpath met the
  // scene (a sphere light's surface too: hit.light >= 0; a camera subpath ends there).
  SurfaceInteraction hit;
  Vec3d wi{0.0};         // unit, toward the previous vertex of its own subpath
  Vec3d direction{0.0};  // at infinity: a light's travel direction, an escaped camera ray's
  Rgb beta{1.0};         // the subpath's throughput on arrival here
  double pdfForward = 0.0, pdfReverse = 0.0;
  int light = -1;           // Light: index into Scene::lights()
  bool atInfinity = false;  // a light at infinity, or a camera ray that escaped (kind Surface)
  bool delta = false;       // the subpath left this vertex along a delta lobe
  bool deltaLight = false;  // Light: a delta sun (a single direction)

  const Vec3d& point() const { return hit.point; }
  const Vec3d& normal() const { return hit.geometry.normal; }
  // True for a surface vertex whose BSDF can be evaluated for a connection (a lobe that is not
  // a delta) and that does not emit.
  bool connectible() const {
    return kind == Kind::Surface && !atInfinity && hit.light < 0 &&
           hasAny(hit.model->flags(), LobeFlags::Diffuse | LobeFlags::Glossy);
  }
};

// The density per unit area at `to` (normal toNormal) of a direction sampled at `from` with
// density `pdfSolidAngle`: pdf |cos| / d^2.
double toAreaDensity(double pdfSolidAngle, const Vec3d& from, const Vec3d& to, const Vec3d& toNormal);

struct SubpathSettings {
  int maxVertices;  // surface vertices at most (the eye or the light not counted)
  int rouletteDepth;
};

// Both return Valid, or the kind of the throughput that was not finite or negative (a BSDF
// sample's weight, sample_value.h) on which the walk ended: the vertices before it are in
// `out`, and the caller drops and counts its sample (render.h), as the path tracer does.
//
// The camera subpath of one camera sample through film point `film`: the eye, then up to
// maxVertices surface vertices; a ray that escapes adds a last vertex at infinity (kind
// Surface, atInfinity). `out` is cleared first and reused (no allocation once it has grown).
SampleValue traceCameraSubpath(const Scene& scene, const Vec2d& film, SampleStream& random,
                               const SubpathSettings& settings, std::vector<PathVertex>& out);

// The light subpath of one light path: the light's vertex, then up to maxVertices surface
// vertices. Empty when no light sends anything.
SampleValue traceLightSubpath(const Scene& scene, const LightEmission& emission, SampleStream& random,
                              const SubpathSettings& settings, std::vector<PathVertex>& out);

// A surface vertex of a light subpath seen by the eye (the strategies with t = 1): where on the
// film and the value to add there, per light path, before any MIS weight:
//   beta f(wi, toward the eye) |cos| / d^2 times the pixel importance (camera.h).
// Nothing when it is behind the camera, off the film (widened by the filter's reach) or hidden.
struct CameraConnection {
  Vec2d film;
  Rgb value;
  Vec3d toEye;  // unit, from the vertex
  double distance;
  double cosTheta;  // at the camera
};
std::optional<CameraConnection> connectToCamera(const Scene& scene, const PathVertex& vertex,
                                                const PixelFilter& filter);

}  // namespace scatterlab
