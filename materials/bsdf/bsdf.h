// The BSDF interface every scatterlab model implements.
//
// Conventions (docs/design.md, "Conventions"; every model, test and caller relies on them):
//  - Models work in the local shading frame: z = shading normal, x = tangent (the
//    anisotropy axis). `Bsdf` below owns the frame and converts world <-> local.
//  - Both directions point away from the surface. `wi` is the given direction (toward the
//    camera / previous vertex), `wo` the sampled one (toward the light).
//  - eval(wi, wo) is the BSDF value f in sr^-1, per linear-RGB channel, WITHOUT the cosine
//    factor: measured data stores f and fitting compares f.
//  - pdf(wi, wo) is the density of sample() per unit solid angle of wo. It is exact: the
//    chi-square kit integrates it and compares with sample()'s histogram.
//  - sample(wi, uLobe, u) returns {wo, weight = f * |cos wo| / pdf, pdf, lobe, eta}, or
//    nothing when sampling fails; never NaN. Random numbers come in; no model owns an RNG.
//  - Delta lobes: eval = 0 and pdf = 0 for every pair; sample() returns the discrete
//    probability of choosing the lobe as pdf and sets LobeFlags::Specular.
//  - Reflection-only models are one-sided: for wi.z <= 0 eval and pdf are 0 and sample()
//    fails. Two-sided surfaces flip the frame in `Bsdf` (wi.z > 0 in the model's frame).
//  - Non-reciprocal transmission takes a TransportMode (radiance or importance).
//  - Colour is linear RGB with Rec.709 primaries.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "materials/core/frame.h"
#include "materials/core/spherical.h"

namespace scatterlab {

// What a lobe is: pbrt's BxDFFlags. Specular means a delta (Dirac) lobe.
enum class LobeFlags : uint32_t {
  None = 0,
  Reflection = 1u << 0,
  Transmission = 1u << 1,
  Diffuse = 1u << 2,
  Glossy = 1u << 3,
  Specular = 1u << 4,
  DiffuseReflection = Diffuse | Reflection,
  GlossyReflection = Glossy | Reflection,
  SpecularReflection = Specular | Reflection,
  GlossyTransmission = Glossy | Transmission,
  DiffuseTransmission = Diffuse | Transmission,
  SpecularTransmission = Specular | Transmission,
};
constexpr LobeFlags operator|(LobeFlags a, LobeFlags b) { return LobeFlags(uint32_t(a) | uint32_t(b)); }
constexpr LobeFlags operator&(LobeFlags a, LobeFlags b) { return LobeFlags(uint32_t(a) & uint32_t(b)); }
constexpr bool hasAny(LobeFlags flags, LobeFlags test) { return (flags & test) != LobeFlags::None; }
std::string toString(LobeFlags flags);

// Whose quantity is being transported through a refraction: radiance (from the camera) is
// scaled by 1/eta^2, importance (from the light) is not (Veach 1997, section 5.2).
enum class TransportMode { Radiance, Importance };

// The transport mode in which energy is counted: the kit's energy checks (albedo, Monte Carlo
// albedo, furnace), the histogram whose delta weights enter the albedo, the explorer's albedo curve. Through
// a refraction, radiance is scaled by 1 / etaRel^2 (the refracted beam's solid angle changes; Veach 1997
// section 5.2): radiance is not a conserved quantity, and its "albedo" exceeds 1 for light leaving a denser
// medium although no energy is created. Power is conserved, and importance transport carries
// it: integral of f(wi, wo, Importance) |cos wo| dwo is the fraction of the power arriving
// from wi that is scattered. For reflection the two modes agree.
template <typename Model> TransportMode energyTransportMode(const Model& model) {
  return hasAny(model.flags(), LobeFlags::Transmission) ? TransportMode::Importance : TransportMode::Radiance;
}

struct BsdfSample {
  Vec3d wo;
  Rgb weight{0.0};   // f * |cos wo| / pdf
  double pdf = 0.0;  // per solid angle, or the discrete probability for a delta lobe
  LobeFlags lobe = LobeFlags::None;
  double eta = 1.0;  // relative index of refraction across the sampled transmission, 1 otherwise

  bool isDelta() const { return hasAny(lobe, LobeFlags::Specular); }
};

// A model in its local frame, for callers that choose the model at run time (the CLI, the
// renderer). Concrete models are `final`, so code templated on the concrete type (the test
// kit, benchmarks) calls them without virtual dispatch.
class BsdfModel {
 public:
  virtual ~BsdfModel() = default;

  virtual Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode mode = TransportMode::Radiance) const = 0;
  virtual double pdf(const Vec3d& wi, const Vec3d& wo,
                     TransportMode mode = TransportMode::Radiance) const = 0;
  virtual std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                           TransportMode mode = TransportMode::Radiance) const = 0;
  // The union of the lobes this model can produce.
  virtual LobeFlags flags() const = 0;
  // True when the model loses no energy by construction for its current parameters (white
  // furnace: directional albedo 1 at every wi); the kit then checks albedo == 1.
  virtual bool isLossless() const { return false; }
  // For a lossless model, how far from 1 its directional albedo may be by construction: 0 for a
  // model exact by construction (the kit's furnace limit is then the quadrature's own error
  // estimate), a tabulated compensation's table error otherwise (docs/validation.md, "White
  // furnace"). Meaningless when isLossless() is false.
  virtual double losslessAccuracy() const { return 0.0; }
  // True when f(wi, wo) = f(wo, wi) (BRDF) or the generalised relation holds (BTDF).
  virtual bool isReciprocal() const { return true; }
  // Index of refraction below the surface (z < 0) relative to above; 1 for models without
  // transmission. The generalised reciprocity check divides f by the squared index on the
  // side of each direction (Veach 1997, eq. 5.14).
  virtual double interiorIndex() const { return 1.0; }
};

// A model placed on a surface: owns the shading frame and converts world <-> local.
// Two-sided: when wi is below the shading normal, both directions are mirrored through the
// tangent plane so that one-sided models see wi.z > 0.
class Bsdf {
 public:
  Bsdf(const BsdfModel& model, const Framed& frame, bool twoSided = true)
      : model_(&model), frame_(frame), twoSided_(twoSided) {}

  Rgb eval(const Vec3d& wiWorld, const Vec3d& woWorld, TransportMode mode = TransportMode::Radiance) const {
    auto [wi, wo] = toModel(wiWorld, woWorld);
    return model_->eval(wi, wo, mode);
  }
  double pdf(const Vec3d& wiWorld, const Vec3d& woWorld, TransportMode mode = TransportMode::Radiance) const {
    auto [wi, wo] = toModel(wiWorld, woWorld);
    return model_->pdf(wi, wo, mode);
  }
  std::optional<BsdfSample> sample(const Vec3d& wiWorld, double uLobe, const Vec2d& u,
                                   TransportMode mode = TransportMode::Radiance) const {
    Vec3d wi = frame_.toLocal(wiWorld);
    const bool flip = twoSided_ && wi.z < 0;
    if (flip) wi.z = -wi.z;
    auto s = model_->sample(wi, uLobe, u, mode);
    if (!s) return s;
    if (flip) s->wo.z = -s->wo.z;
    s->wo = frame_.toWorld(s->wo);
    return s;
  }
  const Framed& frame() const { return frame_; }
  LobeFlags flags() const { return model_->flags(); }

 private:
  std::pair<Vec3d, Vec3d> toModel(const Vec3d& wiWorld, const Vec3d& woWorld) const {
    Vec3d wi = frame_.toLocal(wiWorld), wo = frame_.toLocal(woWorld);
    if (twoSided_ && wi.z < 0) {
      wi.z = -wi.z;
      wo.z = -wo.z;
    }
    return {wi, wo};
  }

  const BsdfModel* model_;
  Framed frame_;
  bool twoSided_;
};

}  // namespace scatterlab
