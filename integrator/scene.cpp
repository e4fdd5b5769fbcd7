#include "integrator/scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "materials/bsdf/lambertian.h"

namespace scatterlab {

int Scene::addMaterial(std::unique_ptr<BsdfModel> model) {
  if (!model) throw std::invalid_argument("Scene::addMaterial: no model");
  models_.push_back(std::move(model));
  materials_.push_back({models_.back().get(), nullptr, 1.0});
  return int(materials_.size()) - 1;
}

int Scene::addCheckerMaterial(std::unique_ptr<BsdfModel> even, std::unique_ptr<BsdfModel> odd,
                              double squareSize) {
  if (!even || !odd) throw std::invalid_argument("Scene::addCheckerMaterial: missing model");
  if (!(squareSize > 0) || !std::isfinite(squareSize))
    throw std::invalid_argument("Scene::addCheckerMaterial: square size must be > 0");
  models_.push_back(std::move(even));
  const BsdfModel* first = models_.back().get();
  models_.push_back(std::move(odd));
  materials_.push_back({first, models_.back().get(), squareSize});
  return int(materials_.size()) - 1;
}

int Scene::addSubsurfaceMaterial(const SubsurfaceMaterial& material, SubsurfaceMode mode) {
  if (!material.profile) throw std::invalid_argument("Scene::addSubsurfaceMaterial: no profile");
  const int id = addMaterial(makeSubsurfaceBoundary(material));
  subsurfaces_.push_back(std::make_unique<SceneSubsurface>(material, mode, *models_.back()));
  materials_[size_t(id)].subsurface = subsurfaces_.back().get();
  return id;
}

void Scene::checkMaterial(int material) const {
  if (material < 0 || material >= int(materials_.size()))
    throw std::invalid_argument("Scene: material id " + std::to_string(material) + " does not exist");
}

int Scene::addShape(bool isSphere, int index) {
  shapes_.push_back({isSphere, index});
  return int(shapes_.size()) - 1;
}

int Scene::addSphere(const Sphere& sphere, int material) {
  checkMaterial(material);
  if (!(sphere.radius > 0) || !std::isfinite(sphere.radius) || !isFinite(sphere.center))
    throw std::invalid_argument("Scene::addSphere: radius must be > 0 and the centre finite");
  Sphere placed = sphere;
  placed.axis = glm::normalize(sphere.axis);
  const int shape = addShape(true, int(spheres_.size()));
  spheres_.push_back({placed, material, -1, shape});
  return shape;
}

int Scene::addSphere(const Transform& objectToWorld, int material) {
  const std::optional<double> scale = objectToWorld.uniformScale();
  if (!scale)
    throw std::invalid_argument(
        "Scene::addSphere: the transform must be a similarity (no shear, no mirror, uniform scale)");
  return addSphere(
      Sphere{objectToWorld.point(Vec3d(0.0)), *scale, glm::normalize(objectToWorld.vector(Vec3d(0, 0, 1)))},
      material);
}

int Scene::addPlane(const Plane& plane, int material) {
  checkMaterial(material);
  Plane placed = plane;
  placed.normal = glm::normalize(plane.normal);
  placed.tangent = plane.tangent - placed.normal * glm::dot(placed.normal, plane.tangent);
  if (!(glm::length(placed.tangent) > 1e-9) || !isFinite(placed.normal) || !isFinite(plane.point))
    throw std::invalid_argument(
        "Scene::addPlane: needs a finite point, a normal and a tangent not parallel to it");
  placed.tangent = glm::normalize(placed.tangent);
  const int shape = addShape(false, int(planes_.size()));
  planes_.push_back({placed, material, shape});
  return shape;
}

int Scene::addSphereLight(const Sphere& sphere, const Rgb& radiance) {
  if (!isFinite(radiance) || radiance.x < 0 || radiance.y < 0 || radiance.z < 0)
    throw std::invalid_argument("Scene::addSphereLight: radiance must be finite and >= 0");
  if (blackMaterial_ < 0) blackMaterial_ = addMaterial(std::make_unique<LambertianBsdf>(Rgb(0.0)));
  const int shape = addSphere(sphere, blackMaterial_);
  sphereLights_.push_back({spheres_.back().geometry, radiance});
  spheres_.back().light = int(sphereLights_.size()) - 1;
  rebuildLightList();
  return shape;
}

void Scene::addSun(const SunLight& sun) {
  suns_.push_back(sun);
  rebuildLightList();
}

void Scene::setEnvironment(Environment environment) {
  environment_ = std::move(environment);
  rebuildLightList();
}

void Scene::rebuildLightList() {
  lights_.clear();
  misLights_.clear();
  if (environment_) {
    lights_.push_back({LightKind::Environment, 0});
    if (environment_->hasMap()) misLights_.push_back({LightKind::Environment, 0});
  }
  for (int i = 0; i < int(sphereLights_.size()); ++i) {
    lights_.push_back({LightKind::Sphere, i});
    misLights_.push_back({LightKind::Sphere, i});
  }
  for (int i = 0; i < int(suns_.size()); ++i) {
    lights_.push_back({LightKind::Sun, i});
    misLights_.push_back({LightKind::Sun, i});
  }
}

const BsdfModel* Scene::modelAt(int material, const Vec2d& uv) const {
  const SurfaceMaterial& m = materials_[material];
  const double parity = std::floor(uv.x / m.checkerSize) + std::floor(uv.y / m.checkerSize);
  return std::fmod(std::abs(parity), 2.0) == 0.0 ? m.model : m.checkerModel;
}

std::optional<SurfaceInteraction> Scene::intersect(const Ray& ray, double tMax) const {
  double nearest = tMax;
  int sphere = -1, plane = -1;
  for (int i = 0; i < int(spheres_.size()); ++i) {
    const double t = spheres_[i].geometry.intersect(ray, 0.0, nearest);
    if (t < nearest) {
      nearest = t;
      sphere = i;
    }
  }
  for (int i = 0; i < int(planes_.size()); ++i) {
    const double t = planes_[i].geometry.intersect(ray, 0.0, nearest);
    if (t < nearest) {
      nearest = t;
      plane = i;
      sphere = -1;
    }
  }
  if (sphere < 0 && plane < 0) return std::nullopt;
  SurfaceInteraction hit;
  hit.t = nearest;
  hit.point = ray.at(nearest);
  int material;
  if (sphere >= 0) {
    const SceneSphere& s = spheres_[sphere];
    hit.geometry = s.geometry.geometryAt(hit.point);
    hit.light = s.light;
    hit.shape = s.shape;
    material = s.material;
    hit.subsurface = materials_[material].subsurface;
    hit.model = materials_[material].checkerModel ? modelAt(material, s.geometry.uvAt(hit.point))
                                                  : materials_[material].model;
  } else {
    const ScenePlane& p = planes_[plane];
    hit.geometry = p.geometry.geometryAt(hit.point);
    hit.shape = p.shape;
    material = p.material;
    hit.subsurface = materials_[material].subsurface;
    hit.model = materials_[material].checkerModel ? modelAt(material, p.geometry.uvAt(hit.point))
                                                  : materials_[material].model;
  }
  return hit;
}

bool Scene::occluded(const Ray& ray, double tMax) const {
  for (const SceneSphere& s : spheres_)
    if (s.geometry.intersect(ray, 0.0, tMax) < tMax) return true;
  for (const ScenePlane& p : planes_)
    if (p.geometry.intersect(ray, 0.0, tMax) < tMax) return true;
  return false;
}

double Scene::intersectShape(int shape, const Ray& ray, double tMin, double tMax) const {
  if (shape < 0 || shape >= int(shapes_.size()))
    throw std::invalid_argument("Scene::intersectShape: no such shape");
  const ShapeRef& ref = shapes_[shape];
  return ref.isSphere ? spheres_[ref.index].geometry.intersect(ray, tMin, tMax)
                      : planes_[ref.index].geometry.intersect(ray, tMin, tMax);
}

SurfaceGeometry Scene::shapeGeometry(int shape, const Vec3d& point) const {
  const ShapeRef& ref = shapes_[size_t(shape)];
  return ref.isSphere ? spheres_[ref.index].geometry.geometryAt(point)
                      : planes_[ref.index].geometry.geometryAt(point);
}

int Scene::lightIndex(LightKind kind, int index) const {
  for (size_t i = 0; i < lights_.size(); ++i)
    if (lights_[i].kind == kind && lights_[i].index == index) return int(i);
  return -1;
}

Sphere Scene::finiteBounds() const {
  if (spheres_.empty()) return Sphere{Vec3d(0.0), 1.0};
  Vec3d lo(Infinity), hi(-Infinity);
  for (const SceneSphere& s : spheres_) {
    lo = glm::min(lo, s.geometry.center - Vec3d(s.geometry.radius));
    hi = glm::max(hi, s.geometry.center + Vec3d(s.geometry.radius));
  }
  const Vec3d center = 0.5 * (lo + hi);
  double radius = 0.0;
  for (const SceneSphere& s : spheres_)
    radius = std::max(radius, glm::length(s.geometry.center - center) + s.geometry.radius);
  return Sphere{center, radius};
}

Ray Scene::rayFromInfinity(const Vec3d& point, const Vec3d& direction) const {
  // Back from `point` past the finite shapes and past every plane the line crosses behind it.
  const Sphere bounds = finiteBounds();
  double back = glm::length(point - bounds.center) + bounds.radius;
  for (const ScenePlane& p : planes_) {
    const double along = glm::dot(direction, p.geometry.normal);
    if (along != 0) back = std::max(back, glm::dot(point - p.geometry.point, p.geometry.normal) / along);
  }
  back = back * (1.0 + 1e-6) + 1.0;
  return Ray{point - back * direction, direction};
}

std::optional<LightSample> Scene::sampleLight(const Vec3d& p, double uSelect, const Vec2d& u,
                                              LightSet set) const {
  const std::vector<LightRef>& candidates = lights(set);
  if (candidates.empty()) return std::nullopt;
  const int count = int(candidates.size());
  const LightRef& light = candidates[std::min(int(uSelect * count), count - 1)];
  std::optional<LightSample> sample;
  switch (light.kind) {
    case LightKind::Environment:
      if (const auto s = environment_->sample(u))
        sample = LightSample{s->direction, Infinity, s->radiance, s->pdf};
      break;
    case LightKind::Sphere: sample = sphereLights_[light.index].sample(p, u); break;
    case LightKind::Sun: sample = suns_[light.index].sample(u); break;
  }
  if (sample && !sample->isDelta) sample->pdf /= count;
  if (sample && sample->isDelta) sample->pdf = 1.0 / count;
  if (sample) sample->light = std::min(int(uSelect * count), count - 1);
  return sample;
}

Rgb Scene::emitted(const SurfaceInteraction& hit, const Vec3d& toward) const {
  if (hit.light < 0 || glm::dot(hit.geometry.normal, toward) <= 0) return Rgb(0.0);
  return sphereLights_[hit.light].radiance;
}

double Scene::emittedPdf(const SurfaceInteraction& hit, const Vec3d& from, LightSet set) const {
  if (hit.light < 0) return 0.0;
  return lightSelectionProbability(set) * sphereLights_[hit.light].pdf(from);
}

}  // namespace scatterlab
