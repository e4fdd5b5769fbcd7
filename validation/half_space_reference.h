// The half-space random walk over many paths, on all cores: the ground truth that every
// diffusion profile is measured against (docs/validation.md section 6). One path and the tally are
// materials/bssrdf/half_space_walk.h; this is their parallel driver (TBB), kept out of the
// materials library, which does no threading (docs/design.md, "Who may include whom").
#pragma once

#include <functional>

#include "materials/bssrdf/half_space_walk.h"

namespace scatterlab {

// Fraction of the paths done, called from worker threads (may be empty).
using WalkProgress = std::function<void(double fraction)>;

// Traces settings.paths paths on settings.threads threads (0: all cores); the same result for
// any thread count. Throws std::invalid_argument naming a setting out of range.
HalfSpaceWalkResult simulateHalfSpace(const HalfSpaceWalkSettings& settings,
                                      const WalkProgress& progress = {});

}  // namespace scatterlab
