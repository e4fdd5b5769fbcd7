// A BSDF whose values are cheap only in bulk: one that lives in Python (docs/python.md, "The kit
// on any object") answers a million directions in one numpy call in about the time it takes to
// answer a few hundred one by one. The kit integrates such a model's pdf and f |cos| over the
// cells of the sphere with integrateCellsInBatches (batched_quadrature.h), which asks for a whole
// level of the quadrature at a time and gives the same numbers as the one-at-a-time quadrature.
#pragma once

#include <span>

#include "materials/bsdf/bsdf.h"

namespace scatterlab {

class BulkEvaluatedBsdf {
 public:
  virtual ~BulkEvaluatedBsdf() = default;
  // f[k] = eval(wi[k], wo[k], mode) and pdf[k] = pdf(wi[k], wo[k], mode) for every k: the values
  // the model's eval and pdf return one at a time.
  virtual void evalAndPdf(std::span<const Vec3d> wi, std::span<const Vec3d> wo, TransportMode mode,
                          std::span<Rgb> f, std::span<double> pdf) const = 0;
};

}  // namespace scatterlab
