// Whether a value the renderer carries (a path's throughput, a sample's radiance) can enter
// the film. A value that is not finite, or has a negative channel, cannot: no light transport
// produces one, so it is a bug in a model (or, in the tests, a fault put there on purpose).
// The path that meets one ends there and says so (PathSample::invalid); the film drops its
// sample and counts it (render.h RenderStatistics), so nothing is lost without a number.
#pragma once

#include <initializer_list>

#include "materials/core/math.h"

namespace scatterlab {

enum class SampleValue { Valid, NonFinite, Negative };

inline SampleValue classifyValue(const Rgb& value) {
  if (!isFinite(value)) return SampleValue::NonFinite;
  if (value.x < 0 || value.y < 0 || value.z < 0) return SampleValue::Negative;
  return SampleValue::Valid;
}

// The film's rule for one sample, shared by every estimator (render.cpp, splat_film.h,
// sppm.cpp): dropped for the invalid weight its path ended on, if it did (`path`), else for the
// first of the values it would add to the film that is not Valid; counted by that kind.
inline SampleValue classifySample(SampleValue path, std::initializer_list<Rgb> values) {
  if (path != SampleValue::Valid) return path;
  for (const Rgb& value : values)
    if (const SampleValue kind = classifyValue(value); kind != SampleValue::Valid) return kind;
  return SampleValue::Valid;
}

}  // namespace scatterlab
