#include "fitting/plugin_model_kernel.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>

#include "materials/registry/plugin_bsdf.h"

namespace scatterlab::fitting {

namespace {

int slotsOf(ParameterKind kind) {
  return kind == ParameterKind::Number ? 1
         : kind == ParameterKind::Rgb  ? 3
         : kind == ParameterKind::Pair ? 2
                                       : 0;
}

// Models built at recently used slot values, per thread: a residual evaluation visits every
// sample at one x (and, for derivatives, at x +- h along each slot), so each model is built once
// per chunk of samples rather than once per sample. At most 2 x 13 + 2 models live at a time.
struct BuiltModel {
  uint64_t kernel = 0;
  std::vector<double> slots;
  std::unique_ptr<BsdfModel> model;
};
constexpr size_t BuiltModelCacheSize = 28;

// The relative step of the central differences: about the cube root of the double epsilon,
// which balances the truncation error (h^2 f''') against round-off (eps f / h).
constexpr double RelativeStep = 6e-6;

}  // namespace

int pluginModelSlots(const MaterialModel& model) {
  int slots = 0;
  for (const ParameterSpec& spec : model.parameters) slots += slotsOf(spec.kind);
  return slots;
}

PluginModelKernel::PluginModelKernel(const MaterialModel& model, MaterialParameters held)
    : model_(&model), held_(std::move(held)) {
  static std::atomic<uint64_t> nextId{1};
  id_ = nextId++;
  for (const ParameterSpec& spec : model.parameters)
    for (int c = 0; c < slotsOf(spec.kind); ++c) slots_.push_back({spec.name, spec.kind, c, spec.range});
}

Rgb PluginModelKernel::evalBuilt(const double* slots, const Vec3d& wi, const Vec3d& wo) const {
  thread_local std::array<BuiltModel, BuiltModelCacheSize> cache;
  thread_local size_t next = 0;
  const size_t n = slots_.size();
  for (const BuiltModel& built : cache)
    if (built.kernel == id_ && std::equal(built.slots.begin(), built.slots.end(), slots, slots + n))
      return built.model->eval(wi, wo);

  MaterialParameters parameters = held_;
  for (size_t i = 0; i < n;) {
    const Slot& slot = slots_[i];
    if (slot.kind == ParameterKind::Number) {
      parameters.set(slot.key, slots[i]);
      i += 1;
    } else if (slot.kind == ParameterKind::Rgb) {
      parameters.set(slot.key, Rgb(slots[i], slots[i + 1], slots[i + 2]));
      i += 3;
    } else {
      parameters.set(slot.key, Vec2d(slots[i], slots[i + 1]));
      i += 2;
    }
  }
  BuiltModel& entry = cache[next];
  next = (next + 1) % BuiltModelCacheSize;
  entry.model = buildPluginBsdf(*model_, parameters);
  entry.kernel = id_;
  entry.slots.assign(slots, slots + n);
  return entry.model->eval(wi, wo);
}

void PluginModelKernel::eval(const double* slots, const Vec3d& wi, const Vec3d& wo, double value[3],
                             double* gradient) const {
  const int n = int(slots_.size());
  if (model_->fitKernel) {
    model_->fitKernel.eval(slots, wi, wo, value, gradient);
    return;
  }
  const Rgb f = evalBuilt(slots, wi, wo);
  for (int c = 0; c < 3; ++c) value[c] = f[c];
  if (!gradient) return;
  std::vector<double> shifted(slots, slots + n);
  for (int i = 0; i < n; ++i) {
    const ValueRange& range = slots_[size_t(i)].range;
    const double x = slots[i];
    const double h = RelativeStep * std::max(std::abs(x), 1.0);
    // Central where both neighbours are allowed values, one-sided at a bound.
    const double lo = range.contains(x - h) ? x - h : x;
    const double hi = range.contains(x + h) ? x + h : x;
    shifted[size_t(i)] = hi;
    const Rgb above = hi == x ? f : evalBuilt(shifted.data(), wi, wo);
    shifted[size_t(i)] = lo;
    const Rgb below = lo == x ? f : evalBuilt(shifted.data(), wi, wo);
    shifted[size_t(i)] = x;
    for (int c = 0; c < 3; ++c) gradient[c * n + i] = hi > lo ? (above[c] - below[c]) / (hi - lo) : 0.0;
  }
}

}  // namespace scatterlab::fitting
