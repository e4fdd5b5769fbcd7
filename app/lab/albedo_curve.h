// Directional albedo against the incident angle: the integral of f |cos wo| over the sphere
// (plus the delta lobes' probability x weight) at each wi, by the kit's own quadrature
// (validation/chi_square.h integrateCells, as validation/energy.h uses it): adaptive Simpson
// per cell of a coarse (cos theta, phi) grid, each cell split at the centroid of the samples
// the model's sampler put there, so that narrow lobes are found. The check's "albedo" row on
// a finer set of angles, to a plot's accuracy (relative 1e-4 per cell). Energy is counted in
// the kit's transport mode (importance through refractions: power).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "materials/bsdf/bsdf.h"

namespace scatterlab {

struct AlbedoCurveOptions {
  double phiDeg = 30.0;
  int cosThetaCells = 16, phiCells = 32;
  size_t probeSamples = 20000;
  uint64_t seed = 1;
};

struct AlbedoPoint {
  double thetaDeg = 0;
  Rgb albedo{0.0};
};

std::vector<AlbedoPoint> directionalAlbedoCurve(const BsdfModel& model, const std::vector<double>& thetaDeg,
                                                const AlbedoCurveOptions& options);

}  // namespace scatterlab
