// A plugin's model in a fit (materials/registry/plugin.h). Every number, rgb and pair value of
// its spec is a shape slot, in the spec's order; the model has no linear terms (it is fitted
// alone, as the built-in models without a linear scale of their whole value are). Its value
// and derivatives come from the kernel its plugin registered (fitting/plugin_fit_kernel.h:
// exact, by automatic differentiation) or, without one, from the model itself: eval of the
// model built at the slots' values, differentiated by central differences (one-sided at a bound
// of the parameter's range), which FitModel::derivativeNotes reports.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "materials/registry/material_model.h"

namespace scatterlab::fitting {

class PluginModelKernel {
 public:
  static constexpr int Terms = 0;

  // `model` is a plugin's registry entry (it outlives the kernel); `held` validated parameters of
  // it, whose non-numeric values (choices, paths) every evaluation keeps.
  PluginModelKernel(const MaterialModel& model, MaterialParameters held);

  int slots() const { return int(slots_.size()); }
  bool numericDerivatives() const { return !model_->fitKernel; }
  const MaterialModel& model() const { return *model_; }

  // value[c] = f_c at `slots` (wi, wo above the surface); with `gradient`, also
  // gradient[c * slots() + i] = d value[c] / d slots[i].
  void eval(const double* slots, const Vec3d& wi, const Vec3d& wo, double value[3], double* gradient) const;

 private:
  struct Slot {
    std::string key;
    ParameterKind kind;
    int component;  // 0 for a number, the channel or component of an rgb or pair
    ValueRange range;
  };

  // f from the model built at `slots` (numeric path).
  Rgb evalBuilt(const double* slots, const Vec3d& wi, const Vec3d& wo) const;

  const MaterialModel* model_;
  MaterialParameters held_;  // the completed description's values; numeric slots overwrite theirs
  std::vector<Slot> slots_;
  uint64_t id_;  // tells this kernel's built models apart in the per-thread cache
};

// The shape slots of a plugin's model: the spec's number (1), rgb (3) and pair (2) parameters.
int pluginModelSlots(const MaterialModel& model);

}  // namespace scatterlab::fitting
