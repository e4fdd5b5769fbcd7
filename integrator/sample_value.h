// Whether a value the renderer carries (a path's throughput, a sample's radiance) can enter
// the film. A value that is not finite, or has a negative channel, cannot: no light transport
// produces one, so it is a bug in a model (or, in the tests, a fault put there on purpose).
// The path that meets one ends there and says so (PathSample::invalid); the film drops its
// sample and counts it (render.h RenderStatistics), so nothing is lost without a number.
#pragma once

#include "materials/core/math.h"

namespace scatterlab {

enum class SampleValue { Valid, NonFinite, Negative };

inline SampleValue classifyValue(const Rgb& value) {
  if (!isFinite(value)) return SampleValue::NonFinite;
  if (value.x < 0 || value.y < 0 || value.z < 0) return SampleValue::Negative;
  return SampleValue::Valid;
}

}  // namespace scatterlab
