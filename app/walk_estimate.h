// How long half-space random walks will take (progress.h, announceWork): a pilot of the walk's
// own kind of paths, run for a fraction of a second, timed and scaled. A pilot sees what a formula would have
// to model: near albedo 1 a path scatters thousands of times before it escapes (the mean
// number of events, (1 - R) / (1 - albedo), grows without bound), and g and eta change it too.
#pragma once

#include <vector>

#include "app/progress.h"
#include "materials/bssrdf/half_space_walk.h"

namespace scatterlab {

// The estimate for running every walk of `walks` in turn; `what` describes the run.
WorkEstimate estimateWalks(const std::string& what, const std::vector<HalfSpaceWalkSettings>& walks);

}  // namespace scatterlab
