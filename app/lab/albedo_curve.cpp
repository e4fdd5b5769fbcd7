#include "app/lab/albedo_curve.h"

#include "validation/bsdf_sampling.h"
#include "validation/chi_square.h"

namespace scatterlab {

std::vector<AlbedoPoint> directionalAlbedoCurve(const BsdfModel& model, const std::vector<double>& thetaDeg,
                                                const AlbedoCurveOptions& options) {
  const SphericalGrid grid{options.cosThetaCells, options.phiCells};
  const TransportMode mode = energyTransportMode(model);
  // A plot needs 1e-4, not the kit's 1e-6; and measured tables are noisy, which would make
  // adaptive quadrature chase the noise.
  QuadratureOptions quadrature;
  quadrature.relativeTolerance = 1e-4;
  quadrature.absoluteTolerance = 1e-4 / grid.cellCount();
  std::vector<AlbedoPoint> curve;
  for (size_t k = 0; k < thetaDeg.size(); ++k) {
    const Vec3d wi = directionFromDegrees(thetaDeg[k], options.phiDeg);
    const SampleHistogram histogram = drawSamples(grid, bsdfDirectionSampler(model, wi, mode),
                                                  options.probeSamples, deriveSeed(options.seed, k));
    // f |cos wo| only: the pdf the kit integrates alongside is not needed here.
    const auto cells = integrateCells(
        grid, [&](const Vec3d& wo) { return model.eval(wi, wo, mode) * std::abs(wo.z); }, histogram.probes,
        quadrature);
    AlbedoPoint point{thetaDeg[k], Rgb(0.0)};
    for (const Rgb& cell : cells) point.albedo += cell;
    for (const DeltaDirection& delta : histogram.deltas) point.albedo += delta.probability * delta.weight;
    curve.push_back(point);
  }
  return curve;
}

}  // namespace scatterlab
