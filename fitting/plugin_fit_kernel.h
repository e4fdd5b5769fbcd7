// A plugin model's kernel for the fitter (materials/registry/material_model.h FitKernelFunction):
// the plugin's templated BRDF instantiated with ceres::Jet, so that a fit of a plugin model gets
// exact derivatives as the built-in models' kernels do (fitting/lobe_kernels.h; docs/design.md,
// "One model code"). Header-only: it is compiled into the plugin.
//
//     struct MyKernel {
//       static constexpr int Slots = 4;  // the spec's number (1), rgb (3), pair (2) values, in order
//       template <typename T> static RgbT<T> eval(const T* slots, const Vec3d& wi, const Vec3d& wo);
//     };
//     model.fitKernel = scatterlab::fitting::fitKernelFunction<MyKernel>();
//
// eval returns f (no cosine) at wi, wo (local frame, both above the surface) for the parameter
// values in `slots`. A model registered without a kernel is fitted with numeric derivatives
// (fit_model.h), which is slower and less accurate.
#pragma once

#include <array>

#include <ceres/jet.h>

#include "materials/registry/material_model.h"

namespace scatterlab::fitting {

template <typename Kernel> FitKernelFunction fitKernelFunction() {
  static_assert(Kernel::Slots > 0, "a kernel has at least one slot (one numeric parameter)");
  return {Kernel::Slots,
          [](const double* slots, const Vec3d& wi, const Vec3d& wo, double value[3], double* gradient) {
            if (!gradient) {
              const Rgb f = Kernel::template eval<double>(slots, wi, wo);
              for (int c = 0; c < 3; ++c) value[c] = f[c];
              return;
            }
            using Jet = ceres::Jet<double, Kernel::Slots>;
            std::array<Jet, Kernel::Slots> x;
            for (int i = 0; i < Kernel::Slots; ++i) x[size_t(i)] = Jet(slots[i], i);
            const RgbT<Jet> f = Kernel::template eval<Jet>(x.data(), wi, wo);
            for (int c = 0; c < 3; ++c) {
              value[c] = f[c].a;
              for (int i = 0; i < Kernel::Slots; ++i) gradient[c * Kernel::Slots + i] = f[c].v[i];
            }
          }};
}

}  // namespace scatterlab::fitting
