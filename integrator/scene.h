// A scene: analytic shapes with materials, lights, an environment and a camera.
//
// Scenes of material spheres hold a handful of shapes, so intersection is a loop over them
// (no acceleration structure: for fewer than ~10 analytic shapes a BVH only adds work), in
// double precision, with no virtual call: spheres and planes live in arrays of their own.
//
// Materials are registry models (materials/registry/) owned by the scene; a surface
// holds a material id. A material is one model or a checkerboard of two (the preview scene's
// ground). Transmissive models are placed with Bsdf(model, frame, twoSided = false) (the side
// of wi is what tells inside from outside); reflection-only models are two-sided.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "integrator/camera.h"
#include "integrator/environment.h"
#include "integrator/interaction.h"
#include "integrator/lights.h"
#include "integrator/shapes.h"
#include "integrator/subsurface.h"
#include "materials/bsdf/bsdf.h"

namespace scatterlab {

// A material of the scene: one model, or a checkerboard of two in the surface's texture
// coordinates (squares of side checkerSize; `model` where floor(u / size) + floor(v / size)
// is even).
struct SurfaceMaterial {
  const BsdfModel* model = nullptr;
  const BsdfModel* checkerModel = nullptr;
  double checkerSize = 1.0;
  const SceneSubsurface* subsurface = nullptr;  // set for a subsurface material (model: its boundary)
};

// One kind of light, as next-event estimation chooses among them.
enum class LightKind { Environment, Sphere, Sun };
struct LightRef {
  LightKind kind;
  int index;  // into Scene::sphereLights() or Scene::suns(); 0 for the environment
};

// Which lights next-event estimation samples. `All` of them (for the light-only estimator),
// or those worth sampling under MIS: there a constant environment is left to BSDF sampling
// alone and its light density counts as 0 in the MIS weights, which stay a partition of
// unity. BSDF sampling already follows f |cos| under a constant radiance (for a Lambertian
// surface the estimate is exact), so sampling that light too only adds work and variance
// (pbrt-v4 does the same for its UniformInfiniteLight; Karlik, Sik, Vevoda, Skrivan &
// Krivanek 2019, "MIS Compensation", give the general argument).
enum class LightSet { All, MisSampled };

class Scene {
 public:
  // Materials; each returns the material id.
  int addMaterial(std::unique_ptr<BsdfModel> model);
  int addCheckerMaterial(std::unique_ptr<BsdfModel> even, std::unique_ptr<BsdfModel> odd, double squareSize);
  // A subsurface material (subsurface.h): its dielectric boundary is the surface's model, and a
  // transmission into it is continued by `mode`. Put it on closed shapes only (spheres).
  int addSubsurfaceMaterial(const SubsurfaceMaterial& material, SubsurfaceMode mode);

  // Shapes; each returns the shape id.
  int addSphere(const Sphere& sphere, int material);
  // The unit sphere at the origin placed by `objectToWorld`, which must be a similarity
  // (rotation, uniform scale, translation; std::invalid_argument otherwise). Its z axis is the
  // pole around which tangents circle.
  int addSphere(const Transform& objectToWorld, int material);
  int addPlane(const Plane& plane, int material);
  // A sphere emitting `radiance` from its outside (an area light); its surface reflects nothing.
  int addSphereLight(const Sphere& sphere, const Rgb& radiance);

  void addSun(const SunLight& sun);
  // The light at infinity; without one (the default) the scene's background is black.
  void setEnvironment(Environment environment);
  void setCamera(const PinholeCamera& camera) { camera_ = camera; }

  const PinholeCamera& camera() const { return camera_; }
  const Environment* environment() const { return environment_ ? &*environment_ : nullptr; }
  const std::vector<SphereLight>& sphereLights() const { return sphereLights_; }
  const std::vector<SunLight>& suns() const { return suns_; }
  int shapeCount() const { return int(shapes_.size()); }
  // True when a subsurface material is in the scene (only the path tracer renders them).
  bool hasSubsurface() const { return !subsurfaces_.empty(); }

  // The nearest surface hit by `ray` in (0, tMax).
  std::optional<SurfaceInteraction> intersect(const Ray& ray, double tMax = Infinity) const;
  // True when any surface lies on the ray in (0, tMax).
  bool occluded(const Ray& ray, double tMax) const;
  // The nearest t in (tMin, tMax) where `ray` meets shape `shape` alone, or Infinity: probe rays
  // of a subsurface material search one object this way.
  double intersectShape(int shape, const Ray& ray, double tMin, double tMax) const;
  // The geometry of shape `shape` at `point` (on it).
  SurfaceGeometry shapeGeometry(int shape, const Vec3d& point) const;

  // The lights of a set, in the order next-event estimation numbers them.
  const std::vector<LightRef>& lights(LightSet set = LightSet::All) const {
    return set == LightSet::All ? lights_ : misLights_;
  }
  // The position of a light in lights(LightSet::All), or -1.
  int lightIndex(LightKind kind, int index) const;
  // A sphere holding every shape of finite size (the spheres, lights included); the unit
  // sphere at the origin when there is none. Light from infinity is aimed at it.
  Sphere finiteBounds() const;
  // A ray along the whole line through `point` in `direction`, starting before the line
  // meets any surface (an infinite plane included): light arriving from infinity.
  Ray rayFromInfinity(const Vec3d& point, const Vec3d& direction) const;

  // ---- Lights, for next-event estimation: one light of the set chosen uniformly, then sampled.
  int lightCount(LightSet set = LightSet::All) const { return int(lights(set).size()); }
  double lightSelectionProbability(LightSet set = LightSet::All) const {
    return lights(set).empty() ? 0.0 : 1.0 / double(lights(set).size());
  }
  // A light sample for the shading point p; its pdf includes the selection probability.
  std::optional<LightSample> sampleLight(const Vec3d& p, double uSelect, const Vec2d& u,
                                         LightSet set = LightSet::All) const;

  // The radiance a ray escaping along `direction` receives from the lights at infinity, each
  // light's share multiplied by weight(pdf) with pdf the density (selection included) with
  // which next-event estimation of `set` would have sampled that light in this direction.
  template <typename Weight>
  Rgb escapedRadiance(const Vec3d& direction, const Weight& weight, LightSet set = LightSet::All) const {
    const double select = lightSelectionProbability(set);
    Rgb sum(0.0);
    if (environment_) {
      const EnvironmentValue value = environment_->evalWithPdf(direction);
      const bool sampled = set == LightSet::All || environment_->hasMap();
      sum += value.radiance * weight(sampled ? select * value.pdf : 0.0);
    }
    for (const SunLight& sun : suns_)
      if (const Rgb l = sun.eval(direction); l != Rgb(0.0)) sum += l * weight(select * sun.pdf(direction));
    return sum;
  }
  // Radiance emitted by a sphere light toward `toward` (a unit vector away from the hit) at
  // `hit`, and the density with which next-event estimation of `set` from `from` would have
  // sampled the light (selection included).
  Rgb emitted(const SurfaceInteraction& hit, const Vec3d& toward) const;
  double emittedPdf(const SurfaceInteraction& hit, const Vec3d& from, LightSet set = LightSet::All) const;

 private:
  struct SceneSphere {
    Sphere geometry;
    int material;
    int light;
    int shape;
  };
  struct ScenePlane {
    Plane geometry;
    int material;
    int shape;
  };
  struct ShapeRef {
    bool isSphere;
    int index;
  };
  int addShape(bool isSphere, int index);
  const BsdfModel* modelAt(int material, const Vec2d& uv) const;
  void checkMaterial(int material) const;
  void rebuildLightList();

  std::vector<std::unique_ptr<BsdfModel>> models_;
  std::vector<SurfaceMaterial> materials_;
  std::vector<std::unique_ptr<SceneSubsurface>> subsurfaces_;
  std::vector<SceneSphere> spheres_;
  std::vector<ScenePlane> planes_;
  std::vector<ShapeRef> shapes_;
  std::vector<SphereLight> sphereLights_;
  std::vector<SunLight> suns_;
  std::optional<Environment> environment_;
  std::vector<LightRef> lights_, misLights_;
  PinholeCamera camera_;
  int blackMaterial_ = -1;
};

}  // namespace scatterlab
