// The setting of the probe chi-square test: exit points found by the probe sampler
// (materials/bssrdf/probe_sampling.h) on the plane z = 0 through the entry point, the origin.
// The sampler's frame is either the plane's own (aligned: the tangent probes run parallel to
// the plane and never find it) or tilted against it, as a shading normal that is not the
// geometric one tilts it: then all three axes find points, and the exact multi-axis density
// differs from a radial shortcut everywhere.
#pragma once

#include <optional>

#include "materials/bssrdf/probe_sampling.h"
#include "materials/core/rng.h"
#include "validation/planar_chi_square.h"

namespace scatterlab {

enum class ProbeFrame { Aligned, Tilted };
const char* toString(ProbeFrame frame);

// Aligned: the standard frame. Tilted: the frame around the normal (0.3, 0.4, 0.866), whose
// three axes meet the plane's normal at cosines 0.3, 0.4 and 0.866 (none lies in the plane).
Framed probeFrame(ProbeFrame frame);

// One probe from the origin with the frame, intersected with the plane: the exit point's
// (x, y), or nothing when the chord misses the plane.
std::optional<Vec2d> probeExitOnPlane(const ProbeSampler& sampler, const Framed& frame, CounterRng& rng);

// The sampler's density per unit area at (x, y, 0), normal +z.
double probeExitPdfOnPlane(const ProbeSampler& sampler, const Framed& frame, const Vec2d& p);

// Rings equal in the channel mixture of the truncated radius CDFs (the density of the aligned
// frame's normal probes), with every channel's r_max added as an edge (the density jumps
// there), out to the largest r_max.
PolarGrid probePolarGrid(const ProbeSampler& sampler, const RadialProfile& profile, int rings, int sectors);

}  // namespace scatterlab
