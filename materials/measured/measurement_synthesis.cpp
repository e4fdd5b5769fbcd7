#include "materials/measured/measurement_synthesis.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "materials/core/rng.h"
#include "materials/measured/half_diff.h"

namespace scatterlab {

namespace {

// Independent random streams per perturbation: enabling one leaves the others' numbers as
// they were.
enum class Stream : uint64_t { Gain = 0, LogNoise = 1, NoiseFloor = 2 };

Rgb standardNormals(CounterRng& rng) {
  Rgb z;
  for (int c = 0; c < 3; ++c) {
    const double u0 = rng.uniform();
    z[c] = standardNormal(u0, rng.uniform());
  }
  return z;
}

}  // namespace

double standardNormal(double u0, double u1) {
  return std::sqrt(-2.0 * std::log1p(-u0)) * std::cos(2.0 * Pi * u1);  // log1p(-u0) = ln(1 - u0), u0 < 1
}

MeasurementSynthesizer::MeasurementSynthesizer(std::vector<const BsdfModel*> components,
                                               const MeasurementPerturbation& perturbation)
    : components_(std::move(components)), perturbation_(perturbation) {
  const auto nonNegative = [](double x) { return std::isfinite(x) && x >= 0; };
  if (!nonNegative(perturbation.gainSigma) || !nonNegative(perturbation.logSigma) ||
      !nonNegative(perturbation.noiseFloor))
    throw std::invalid_argument("measurement perturbation: sigmas and noise floor must be finite and >= 0");
  if (perturbation.missingAboveDeg) {
    const double deg = *perturbation.missingAboveDeg;
    if (!(deg > 0 && deg <= 90))
      throw std::invalid_argument("measurement perturbation: cut-off must be in (0, 90]");
    cosMissingAbove_ = std::cos(radians(deg));
  }
  if (perturbation.gainSigma > 0) {
    CounterRng rng(deriveSeed(perturbation.seed, uint64_t(Stream::Gain)), 0);
    const Rgb z = standardNormals(rng);
    for (int c = 0; c < 3; ++c) gains_[c] = std::exp(perturbation.gainSigma * z[c]);
  }
}

Rgb MeasurementSynthesizer::groundTruth(size_t cell) const {
  const merl::CellCoordinates c = merl::cellCoordinates(cell);
  const auto [wi, wo] =
      directionsFromHalfDiff(merl::thetaHalfAt(c.thetaHalf + 0.5), 0.0, merl::thetaDiffAt(c.thetaDiff + 0.5),
                             merl::phiDiffAt(c.phiDiff + 0.5));
  Rgb f(0.0);
  if (!(wi.z > 0) || !(wo.z > 0)) return f;
  for (const BsdfModel* model : components_) f += model->eval(wi, wo);
  if (!isFinite(f))
    throw std::logic_error("measurement synthesis: a model returned a non-finite value at cell " +
                           std::to_string(cell));
  return f;
}

void MeasurementSynthesizer::fillThetaHalfCells(int begin, int end, MerlTable& table) const {
  const MeasurementPerturbation& p = perturbation_;
  const uint64_t logSeed = deriveSeed(p.seed, uint64_t(Stream::LogNoise));
  const uint64_t floorSeed = deriveSeed(p.seed, uint64_t(Stream::NoiseFloor));
  for (int th = begin; th < end; ++th) {
    for (int td = 0; td < merl::ThetaDiffCells; ++td) {
      for (int pd = 0; pd < merl::PhiDiffCells; ++pd) {
        const size_t cell = merl::cellIndex(th, td, pd);
        if (p.missingAboveDeg) {
          const auto [cosI, cosO] = polarCosinesFromHalfDiff(
              merl::thetaHalfAt(th + 0.5), merl::thetaDiffAt(td + 0.5), merl::phiDiffAt(pd + 0.5));
          if (cosI < cosMissingAbove_ || cosO < cosMissingAbove_) {
            table.setMissing(cell);
            continue;
          }
        }
        Rgb f = groundTruth(cell) * gains_;
        if (p.logSigma > 0) {
          CounterRng rng(logSeed, cell);
          const Rgb z = standardNormals(rng);
          for (int c = 0; c < 3; ++c) f[c] *= std::exp(p.logSigma * z[c] - 0.5 * p.logSigma * p.logSigma);
        }
        if (p.noiseFloor > 0) {
          CounterRng rng(floorSeed, cell);
          const Rgb z = standardNormals(rng);
          for (int c = 0; c < 3; ++c) {
            const double sigma = std::sqrt(p.noiseFloor * p.noiseFloor + p.noiseFloor * f[c]);
            f[c] = std::max(0.0, f[c] + sigma * z[c]);
          }
        }
        table.setRgb(cell, f);
      }
    }
  }
}

MerlTable MeasurementSynthesizer::synthesize() const {
  MerlTable table;
  fillThetaHalfCells(0, merl::ThetaHalfCells, table);
  return table;
}

}  // namespace scatterlab
