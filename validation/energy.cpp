#include "validation/energy.h"

#include <algorithm>

namespace scatterlab {

double normalisationTolerance(double failureProbability, size_t samples, double quadratureError) {
  const double p = failureProbability;
  return std::max(NormalisationTarget, quadratureError) +
         4.0 * std::sqrt(p * (1.0 - p) / double(std::max<size_t>(samples, 1)));
}

EnergyResult energyFromIntegrals(const std::vector<glm::dvec4>& cellIntegrals,
                                 const std::vector<glm::dvec4>& cellErrors,
                                 const SampleHistogram& histogram) {
  EnergyResult r;
  glm::dvec4 total(0.0), error(0.0);
  for (const glm::dvec4& v : cellIntegrals) total += v;
  for (const glm::dvec4& e : cellErrors) error += e;
  r.pdfIntegral = total.x;
  r.pdfIntegralError = error.x;
  r.albedo = Rgb(total.y, total.z, total.w);
  r.albedoError = Rgb(error.y, error.z, error.w);
  for (const DeltaDirection& d : histogram.deltas) {
    r.deltaProbability += d.probability;
    r.albedo += d.probability * d.weight;  // E[weight] restricted to the delta lobe
  }
  r.failureProbability = double(histogram.failedSamples) / double(std::max<size_t>(histogram.sampleCount, 1));
  r.normalisationError = std::abs(r.pdfIntegral + r.deltaProbability - (1.0 - r.failureProbability));
  // The binomial noise of the counted failures, at the larger of the counted fraction and the
  // one the pdf predicts (1 - its integral): with a failure probability of 1e-5 and 2e4 samples
  // the count is usually 0, and a standard error taken from that 0 would be 0.
  const double predictedFailure = std::clamp(1.0 - r.pdfIntegral - r.deltaProbability, 0.0, 1.0);
  r.normalisationTolerance = normalisationTolerance(std::max(r.failureProbability, predictedFailure),
                                                    histogram.sampleCount, r.pdfIntegralError);
  return r;
}

std::vector<double> pdfPart(const std::vector<glm::dvec4>& cellIntegrals) {
  std::vector<double> out(cellIntegrals.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = cellIntegrals[i].x;
  return out;
}

}  // namespace scatterlab
