// Normalisation and energy (docs/validation.md section 3), from one quadrature pass that
// integrates (pdf, f|cos| r, g, b) over every cell of the sphere.
#pragma once

#include <vector>

#include "materials/bsdf/bsdf.h"
#include "validation/batched_quadrature.h"
#include "validation/bulk_evaluated_bsdf.h"
#include "validation/chi_square.h"

namespace scatterlab {

// The integrand of integrateEnergyCells: x = pdf, yzw = f |cos wo| per channel, in `mode`
// (energyTransportMode(model) for the energy checks: bsdf_sampling.h says why).
template <typename Model>
auto bsdfEnergyIntegrand(const Model& model, const Vec3d& wi, TransportMode mode = TransportMode::Radiance) {
  return [&model, wi, mode](const Vec3d& wo) {
    const Rgb f = model.eval(wi, wo, mode) * std::abs(wo.z);
    return glm::dvec4(model.pdf(wi, wo, mode), f.x, f.y, f.z);
  };
}

// integrateCellsWithError of bsdfEnergyIntegrand: (pdf, f |cos wo|) over every cell. A model that
// is a BulkEvaluatedBsdf is asked for its values a quadrature level at a time
// (integrateCellsInBatches); the numbers are the same.
inline CellIntegrals<glm::dvec4> integrateEnergyCells(const BsdfModel& model, const Vec3d& wi,
                                                      TransportMode mode, const SphericalGrid& grid,
                                                      const std::vector<Vec2d>& probes,
                                                      const QuadratureOptions& options) {
  const auto* bulk = dynamic_cast<const BulkEvaluatedBsdf*>(&model);
  if (!bulk) return integrateCellsWithError(grid, bsdfEnergyIntegrand(model, wi, mode), probes, options);
  std::vector<Vec3d> incident;
  std::vector<Rgb> f;
  std::vector<double> pdf;
  const auto evaluate = [&](std::span<const Vec3d> wo, std::span<glm::dvec4> values) {
    incident.assign(wo.size(), wi);
    f.resize(wo.size());
    pdf.resize(wo.size());
    bulk->evalAndPdf(incident, wo, mode, f, pdf);
    for (size_t k = 0; k < wo.size(); ++k) {
      const Rgb fCos = f[k] * std::abs(wo[k].z);  // as bsdfEnergyIntegrand computes it
      values[k] = glm::dvec4(pdf[k], fCos.x, fCos.y, fCos.z);
    }
  };
  return integrateCellsInBatches<glm::dvec4>(grid, evaluate, probes, options);
}

// The integral of pdf(wi, wo) over every cell (the chi-square's expected counts alone), in bulk for
// a BulkEvaluatedBsdf as integrateEnergyCells; the numbers are those of integrateCellsWithError.
inline CellIntegrals<double> integratePdfCells(const BsdfModel& model, const Vec3d& wi, TransportMode mode,
                                               const SphericalGrid& grid, const std::vector<Vec2d>& probes,
                                               const QuadratureOptions& options) {
  const auto* bulk = dynamic_cast<const BulkEvaluatedBsdf*>(&model);
  if (!bulk)
    return integrateCellsWithError(
        grid, [&](const Vec3d& wo) { return model.pdf(wi, wo, mode); }, probes, options);
  std::vector<Vec3d> incident;
  std::vector<Rgb> f;
  const auto evaluate = [&](std::span<const Vec3d> wo, std::span<double> values) {
    incident.assign(wo.size(), wi);
    f.resize(wo.size());
    bulk->evalAndPdf(incident, wo, mode, f, values);
  };
  return integrateCellsInBatches<double>(grid, evaluate, probes, options);
}

struct EnergyResult {
  double pdfIntegral = 0.0;         // integral of pdf() over the sphere
  double pdfIntegralError = 0.0;    // the quadrature's own error estimate of pdfIntegral
  double deltaProbability = 0.0;    // total discrete probability of the delta directions seen
  double failureProbability = 0.0;  // fraction of sample() calls that returned nothing
  double normalisationError = 0.0;  // |pdfIntegral + deltaProbability - (1 - failureProbability)|
  double normalisationTolerance = 0.0;
  Rgb albedo{0.0};       // integral of f |cos wo| (quadrature) + delta lobes
  Rgb albedoError{0.0};  // the quadrature's own error estimate of albedo (delta lobes are exact)
};

// The normalisation check's target: the pdf integrates to 1 - P(failure) within 1e-5, where
// the quadrature's own error estimate is below that (docs/validation.md section 3).
inline constexpr double NormalisationTarget = 1e-5;
// Beyond this error estimate the quadrature has not resolved the pdf, and the check fails
// whatever the integral: no tolerance is widened past it.
inline constexpr double NormalisationQuadratureLimit = 1e-3;

// Tolerance of the normalisation check: NormalisationTarget, or the quadrature's error estimate
// where that is larger, plus 4 standard errors of the failure fraction (binomial noise: P(failure)
// is counted, not computed), taken at the larger of the counted and the predicted probability.
double normalisationTolerance(double failureProbability, size_t samples, double quadratureError);

EnergyResult energyFromIntegrals(const std::vector<glm::dvec4>& cellIntegrals,
                                 const std::vector<glm::dvec4>& cellErrors, const SampleHistogram& histogram);

// The pdf part of the cell integrals as a vector of scalars (for expectedCounts).
std::vector<double> pdfPart(const std::vector<glm::dvec4>& cellIntegrals);

}  // namespace scatterlab
