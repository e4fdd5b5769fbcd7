// Choosing one lobe of a mixture with a uniform number, as pbrt-v4's SampleDiscrete
// (src/pbrt/util/sampling.h) does without its division by the sum, and as Mitsuba's blendbsdf
// does for two: lobe i is chosen when cdf_{i-1} <= uLobe < cdf_i, with cdf_i = p_0 + ... + p_i
// accumulated left to right, and the position of uLobe inside that interval,
// (uLobe - cdf_{i-1}) / p_i, is returned as a fresh number, uniform on [0, 1) given the choice,
// for the chosen lobe to use (a nested choice, the compensation lobe of a rough dielectric, a
// blend's component). Every model with more than one sampling lobe chooses through chooseLobe
// (docs/design.md, "How to add a model").
//
// The rule for probabilities that do not sum to exactly 1:
//  - A lobe with p_i <= 0 (or NaN) is skipped: it is never chosen and adds nothing to the cdf.
//  - Probabilities are not normalised: the comparisons are exactly `uLobe < cdf_i`, so a caller
//    that computes p and 1 - p gets the same choice as the comparison `uLobe < p`. Probabilities
//    summing to slightly above 1 (rounding) shorten the last lobe's interval by that excess;
//    summing to slightly below 1, the uLobe beyond the total goes to the last lobe with p_i > 0
//    (with remapped u = OneMinusEpsilon). Both are meant for rounding (~1e-16): a caller whose
//    weights do not sum to 1 by construction divides them by their total first.
//  - With no positive probability no lobe can be chosen: lobe = -1 (u = uLobe).
// The remapped u is clamped to [0, OneMinusEpsilon]: the division can round up to 1 when uLobe is
// just below cdf_i, and a sampler given u = 1 may leave its domain (log(1 - u), a table's end).
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>

namespace scatterlab {

// The largest double below 1, 1 - 2^-53.
inline constexpr double OneMinusEpsilon = 0x1.fffffffffffffp-1;

struct LobeChoice {
  int lobe;  // index into the probabilities; -1 when none is positive
  double u;  // uLobe remapped to [0, 1) within the chosen lobe's interval
};

// uLobe in [0, 1). Allocation-free and branch-light: called once per BSDF sample.
inline LobeChoice chooseLobe(double uLobe, std::span<const double> probabilities) {
  double lower = 0.0;  // cdf_{i-1}
  int last = -1;       // the last lobe with p > 0 so far: takes a uLobe beyond the total
  for (size_t i = 0; i < probabilities.size(); ++i) {
    const double p = probabilities[i];
    if (!(p > 0)) continue;
    last = int(i);
    const double upper = lower + p;
    if (uLobe < upper) return {int(i), std::clamp((uLobe - lower) / p, 0.0, OneMinusEpsilon)};
    lower = upper;
  }
  return {last, last < 0 ? uLobe : OneMinusEpsilon};
}

// Two lobes: the first with probability p, the second with 1 - p. Lobe 0 exactly when uLobe < p
// (p >= 1 always chooses it, p <= 0 never), else lobe 1 (-1 for a NaN p).
inline LobeChoice chooseLobe(double uLobe, double p) {
  const double probabilities[2] = {p, 1.0 - p};
  return chooseLobe(uLobe, probabilities);
}

}  // namespace scatterlab
