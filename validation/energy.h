// Normalisation and energy (docs/validation.md section 3), from one quadrature pass that
// integrates (pdf, f|cos| r, g, b) over every cell of the sphere.
#pragma once

#include <vector>

#include "materials/bsdf/bsdf.h"
#include "validation/chi_square.h"

namespace scatterlab {

// The integrand for bsdfCellIntegrals: x = pdf, yzw = f |cos wo| per channel, in `mode`
// (energyTransportMode(model) for the energy checks: bsdf_sampling.h says why).
template <typename Model>
auto bsdfEnergyIntegrand(const Model& model, const Vec3d& wi, TransportMode mode = TransportMode::Radiance) {
  return [&model, wi, mode](const Vec3d& wo) {
    const Rgb f = model.eval(wi, wo, mode) * std::abs(wo.z);
    return glm::dvec4(model.pdf(wi, wo, mode), f.x, f.y, f.z);
  };
}

struct EnergyResult {
  double pdfIntegral = 0.0;         // integral of pdf() over the sphere
  double deltaProbability = 0.0;    // total discrete probability of the delta directions seen
  double failureProbability = 0.0;  // fraction of sample() calls that returned nothing
  double normalisationError = 0.0;  // |pdfIntegral + deltaProbability - (1 - failureProbability)|
  double normalisationTolerance = 0.0;
  Rgb albedo{0.0};  // integral of f |cos wo| (quadrature) + delta lobes
};

// Tolerance of the normalisation check: 1e-3 (docs/validation.md section 3), widened to 4 standard errors
// of the estimated failure probability when that is the larger (binomial noise).
double normalisationTolerance(double failureProbability, size_t samples);

EnergyResult energyFromIntegrals(const std::vector<glm::dvec4>& cellIntegrals,
                                 const SampleHistogram& histogram);

// The pdf part of the cell integrals as a vector of scalars (for expectedCounts).
std::vector<double> pdfPart(const std::vector<glm::dvec4>& cellIntegrals);

}  // namespace scatterlab
