// Where a ray met the scene: the point, its geometry, the material's model there and what the
// point is besides (a light, the boundary of a subsurface medium). The renderer's estimators
// and the subsurface continuations (subsurface.h) all work on it.
#pragma once

#include "integrator/ray.h"
#include "integrator/shapes.h"
#include "materials/bsdf/bsdf.h"

namespace scatterlab {

struct SceneSubsurface;

struct SurfaceInteraction {
  double t = Infinity;
  Vec3d point{0.0};
  SurfaceGeometry geometry{};
  const BsdfModel* model = nullptr;             // the material's model at this point
  int shape = -1;                               // Scene::shape index
  int light = -1;                               // index into Scene::sphereLights(), or -1: not an emitter
  const SceneSubsurface* subsurface = nullptr;  // the medium below, for a subsurface material

  // True when the model must not be mirrored to the front side (it has transmission).
  bool twoSided() const { return !hasAny(model->flags(), LobeFlags::Transmission); }
  // The shading frame: the shape's tangent is already orthogonal to the normal and of unit
  // length where it exists (shapes.h), so it is used as it is.
  Bsdf bsdf() const {
    const Framed frame =
        geometry.tangent == Vec3d(0.0)
            ? Framed::fromNormal(geometry.normal)
            : Framed(geometry.tangent, glm::cross(geometry.normal, geometry.tangent), geometry.normal);
    return Bsdf(*model, frame, twoSided());
  }
};

}  // namespace scatterlab
