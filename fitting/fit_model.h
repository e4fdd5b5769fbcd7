// The model a BRDF fit adjusts: a sum of registry models ("components": a diffuse term plus
// one to three specular lobes, or one model alone), each split into linear RGB scales and
// shape parameters (lobe_kernels.h), with the fitted parameters in one vector x.
//
// Which parameters are fitted: every linear scale (per channel) and shape parameter of a
// component that its description does not give. A value given in the description
// ({"type": "ngan-cook-torrance", "eta": 0.5}) is held. Bounds are the registry's ranges.
// Because measured (MERL) data is isotropic:
//  - a [x, y] pair (alpha, exponent) is fitted as one value used for both;
//  - Lafortune's cy follows cx (Ngan's Cxy) unless one of them is given;
//  - Disney's "anisotropic" is held at 0 unless given.
// The conductor's complex index is held when the spec gives it ("metal", or "eta" and "k");
// otherwise it is fitted per channel as the normal-incidence reflectance "f0" and the "edge_tint"
// (Gulbrandsen 2014; lobe_kernels.h FittedIndexConductorKernel), in [0.001, 0.999] and
// [0, 1], and the written material holds the (eta, k) they determine; such a conductor carries
// its whole value in its Fresnel factor and is fitted alone. A conductor with a given index
// carries an RGB "scale" (the weight the fitted material blends it with); given as white,
// {"type": "conductor", "eta": 1, "k": 1e8} (F = 1 to round-off, WhiteConductorSpec), it is the
// classic specular lobe of a diffuse-plus-specular fit, its colour and strength the scale. Repeated lobes
// (--lobes N) hold their diffuse terms (kd of Phong, Blinn-Phong, Lafortune) at 0, so that only one term is
// diffuse. perChannelShape: each shared scalar shape parameter becomes one per channel (the kernel is then
// evaluated once per channel).
//
// Models that cannot be fitted: those with delta lobes (no BRDF values to compare), with
// transmission, whose kernels read precomputed tables (rough-plastic, Kulla-Conty
// compensation), blends (sums are the fitter's own business) and measured tables.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <ceres/jet.h>
#include <nlohmann/json.hpp>

#include "fitting/lobe_kernels.h"
#include "fitting/plugin_model_kernel.h"
#include "materials/registry/parameter_spec.h"

namespace scatterlab::fitting {

// How the initial grid spaces a shape parameter's values: evenly, or evenly in the log
// (roughness and exponents, which span decades).
enum class GridSpacing { Linear, Log };

enum class ParameterRole { Scale, Shape };

struct FitParameter {
  std::string name;  // "ngan-cook-torrance.roughness", "lambertian.albedo.g"
  size_t component = 0;
  std::string key;   // the registry key ("scale" for a conductor's blend weight)
  int channel = -1;  // 0..2 for a channel's value, -1 for a value shared by the channels
  ParameterRole role = ParameterRole::Shape;
  double lower = 0, upper = 1;  // from the registry range (an open end nudged inside)
  double start = 0;             // the registry default, clamped to the bounds
  GridSpacing spacing = GridSpacing::Linear;
};

using FitKernelVariant =
    std::variant<LambertianKernel, OrenNayarKernel, EonKernel, NormalizedPhongKernel<PhongLobe>,
                 NormalizedPhongKernel<BlinnPhongLobe>, LafortuneKernel, WardKernel, NganWardKernel,
                 AshikhminShirleyKernel, NganAshikhminShirleyKernel, NganCookTorranceKernel,
                 ConductorKernel<GgxDistribution>, ConductorKernel<BeckmannDistribution>,
                 FittedIndexConductorKernel<GgxDistribution>,
                 FittedIndexConductorKernel<BeckmannDistribution>, DisneyKernel, PluginModelKernel>;

inline constexpr int MaxSlots = 13;
inline constexpr int MaxTerms = 2;

struct FitComponent {
  std::string label;  // the type, or "type#k" when the type appears more than once
  std::string type;
  nlohmann::json description;  // the registry material: completed, held values as given
  FitKernelVariant kernel;
  bool perChannel = false;  // shape evaluated once per channel
  // Per evaluation (one, or one per channel) and slot: the parameter index, or -1 (held).
  std::array<std::array<int, MaxSlots>, 3> slotParameter{};
  std::array<double, MaxSlots> heldSlot{};
  // Per linear term and channel: the parameter index, or -1 (held at heldTerm).
  std::array<std::array<int, 3>, MaxTerms> termParameter{};
  std::array<Rgb, MaxTerms> heldTerm{};
  int slots = 0, terms = 0;
  // True when every term is a registry parameter that scales the whole model (the fitted
  // material can then carry the component at any weight by dividing its scales).
  bool scalable = false;
  // The terms' registry keys ("scale" for the blend weight of a conductor).
  std::array<std::string, MaxTerms> termKeys{};
  // Where each shape key's values sit among the slots (1 number, 2 pair, 3 rgb).
  struct ShapeLayout {
    std::string key;
    int firstSlot = 0, slotCount = 1;
  };
  std::vector<ShapeLayout> shapeLayout;
  // A conductor whose index is fitted as f0 and edge tint (written as eta and k).
  bool fittedIndex = false;
  // Part of the value is not scaled by any linear term (eon, disney, ashikhmin-shirley, a
  // conductor with a fitted index): such a model is fitted alone.
  bool hasRest = false;
};

// A part of the fitted model as a registry material, with how the written material must
// weight it (material_writer.h): a scalable part carries its RGB scales under scaleKeys
// (divided by its weight when written); any other part must be carried with `weight`.
struct FittedPart {
  nlohmann::json material;
  bool scalable = false;
  std::vector<std::string> scaleKeys;
  Rgb weight{1.0};
};

class FitModel {
 public:
  // Throws MaterialError (names the component and key) for a model that cannot be fitted or
  // an invalid description.
  FitModel(const std::vector<nlohmann::json>& components, bool perChannelShape);

  const std::vector<FitComponent>& components() const { return components_; }
  const std::vector<FitParameter>& parameters() const { return parameters_; }
  size_t parameterCount() const { return parameters_.size(); }
  bool perChannelShape() const { return perChannelShape_; }
  std::vector<double> startValues() const;
  // Indices of the parameters of each role.
  std::vector<size_t> parametersOf(ParameterRole role) const;

  // The model's value per channel at (wi, wo), both above the surface; with Derivatives,
  // also rows[c * parameterCount() + k] = d value[c] / d x[k] (rows are overwritten).
  template <bool Derivatives>
  void evaluate(const double* x, const Vec3d& wi, const Vec3d& wo, double value[3], double* rows) const;

  // The fitted model at x as registry materials: one part per component, or one per channel
  // for a component with per-channel shapes (its scales and weight then zero in the other
  // channels). The parts' sum is the model.
  std::vector<FittedPart> fittedParts(const double* x) const;

  // Each component's value of its linear terms and of the rest at the shape parameters of
  // x (scales ignored), for the closed-form solve of the scales: terms[k][j] is component
  // k's term j, per channel.
  void evaluateTerms(const double* x, const Vec3d& wi, const Vec3d& wo,
                     std::vector<std::array<Rgb, MaxTerms>>& terms, std::vector<Rgb>& rests) const;

  // How the derivatives are computed where it is not the usual automatic differentiation:
  // one line per plugin component without a fit kernel (plugin_model_kernel.h).
  std::vector<std::string> derivativeNotes() const;

 private:
  void addComponent(const nlohmann::json& description, const std::string& label, bool repeated);

  std::vector<FitComponent> components_;
  std::vector<FitParameter> parameters_;
  bool perChannelShape_;
};

// The white specular lobe of diffuse-plus-specular fits ("lambertian+" + WhiteConductorSpec):
// a GGX conductor with F = 1 to round-off, coloured and weighted by its fitted scale.
inline constexpr const char* WhiteConductorSpec = R"({"type":"conductor","eta":1,"k":1e8})";

// Parses --model: registry types joined by '+' ("lambertian+ngan-cook-torrance"), where
// any part may be a JSON object instead of a name ({"type": "conductor", "distribution":
// "beckmann"}); or a JSON array of such objects. `lobes` (1..3) repeats the last component.
// Throws MaterialError naming the part at fault.
std::vector<nlohmann::json> parseModelSpec(const std::string& spec, int lobes = 1);

// The registry types the fitter accepts, and why the others are refused.
std::vector<std::string> fittableModels();

// ---- evaluation (templated on whether derivatives are wanted) ----

namespace detail {

template <bool Derivatives, typename Kernel>
void evaluateComponent(const Kernel& kernel, const FitComponent& comp, const double* x, size_t p,
                       const Vec3d& wi, const Vec3d& wo, double value[3], double* rows) {
  constexpr int S = Kernel::Slots;
  constexpr int K = Kernel::Terms > 0 ? Kernel::Terms : 1;
  const int evaluations = comp.perChannel ? 3 : 1;
  const auto scaleOf = [&](int j, int c) {
    const int index = comp.termParameter[size_t(j)][size_t(c)];
    return index >= 0 ? x[index] : comp.heldTerm[size_t(j)][c];
  };
  for (int e = 0; e < evaluations; ++e) {
    const auto& slotIndex = comp.slotParameter[size_t(e)];
    const int cBegin = comp.perChannel ? e : 0, cEnd = comp.perChannel ? e + 1 : 3;
    if constexpr (!Derivatives || S == 0) {
      std::array<double, (S > 0 ? S : 1)> slots{};
      for (int i = 0; i < S; ++i)
        slots[size_t(i)] = slotIndex[size_t(i)] >= 0 ? x[slotIndex[size_t(i)]] : comp.heldSlot[size_t(i)];
      std::array<Rgb, K> terms;
      Rgb rest;
      kernel.eval(slots.data(), wi, wo, terms.data(), rest);
      for (int c = cBegin; c < cEnd; ++c) {
        for (int j = 0; j < Kernel::Terms; ++j) {
          value[c] += scaleOf(j, c) * terms[size_t(j)][c];
          if constexpr (Derivatives) {
            const int index = comp.termParameter[size_t(j)][size_t(c)];
            if (index >= 0) rows[size_t(c) * p + size_t(index)] += terms[size_t(j)][c];
          }
        }
        value[c] += rest[c];
      }
    } else {
      using Jet = ceres::Jet<double, S>;
      std::array<Jet, S> slots;
      for (int i = 0; i < S; ++i) {
        const int index = slotIndex[size_t(i)];
        slots[size_t(i)] = index >= 0 ? Jet(x[index], i) : Jet(comp.heldSlot[size_t(i)]);
      }
      std::array<RgbT<Jet>, K> terms;
      RgbT<Jet> rest;
      kernel.eval(slots.data(), wi, wo, terms.data(), rest);
      for (int c = cBegin; c < cEnd; ++c) {
        double* row = rows + size_t(c) * p;
        const auto addSlots = [&](const Jet& jet, double factor) {
          for (int i = 0; i < S; ++i)
            if (slotIndex[size_t(i)] >= 0) row[slotIndex[size_t(i)]] += factor * jet.v[i];
        };
        for (int j = 0; j < Kernel::Terms; ++j) {
          const Jet& t = terms[size_t(j)][c];
          const double scale = scaleOf(j, c);
          value[c] += scale * t.a;
          const int index = comp.termParameter[size_t(j)][size_t(c)];
          if (index >= 0) row[index] += t.a;
          addSlots(t, scale);
        }
        value[c] += rest[c].a;
        addSlots(rest[c], 1.0);
      }
    }
  }
}

// A plugin's model (plugin_model_kernel.h): the same accumulation over the slots as above, its
// values and derivatives from the kernel.
template <bool Derivatives> void evaluateComponent(const PluginModelKernel& kernel, const FitComponent& comp,
                                                   const double* x, size_t p, const Vec3d& wi,
                                                   const Vec3d& wo, double value[3], double* rows) {
  const int slots = kernel.slots();
  const int evaluations = comp.perChannel ? 3 : 1;
  std::array<double, MaxSlots> s{};
  std::array<double, 3 * MaxSlots> gradient{};
  for (int e = 0; e < evaluations; ++e) {
    const auto& slotIndex = comp.slotParameter[size_t(e)];
    for (int i = 0; i < slots; ++i)
      s[size_t(i)] = slotIndex[size_t(i)] >= 0 ? x[slotIndex[size_t(i)]] : comp.heldSlot[size_t(i)];
    double f[3];
    kernel.eval(s.data(), wi, wo, f, Derivatives ? gradient.data() : nullptr);
    const int cBegin = comp.perChannel ? e : 0, cEnd = comp.perChannel ? e + 1 : 3;
    for (int c = cBegin; c < cEnd; ++c) {
      value[c] += f[c];
      if constexpr (Derivatives)
        for (int i = 0; i < slots; ++i)
          if (slotIndex[size_t(i)] >= 0)
            rows[size_t(c) * p + size_t(slotIndex[size_t(i)])] += gradient[size_t(c * slots + i)];
    }
  }
}

}  // namespace detail

template <bool Derivatives> void FitModel::evaluate(const double* x, const Vec3d& wi, const Vec3d& wo,
                                                    double value[3], double* rows) const {
  const size_t p = parameters_.size();
  value[0] = value[1] = value[2] = 0.0;
  if constexpr (Derivatives) std::fill(rows, rows + 3 * p, 0.0);
  for (const FitComponent& comp : components_)
    std::visit(
        [&](const auto& kernel) {
          detail::evaluateComponent<Derivatives>(kernel, comp, x, p, wi, wo, value, rows);
        },
        comp.kernel);
}

}  // namespace scatterlab::fitting
