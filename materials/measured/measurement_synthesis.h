// Measured-style MERL tables from ground-truth models, perturbed the way a gonioreflectometer
// measurement would be. scatterlab ships no measurements (the MERL database is licensed for
// research only); it makes its own from published fits (ngan_fits.h) or any material.
//
// A cell's value is the sum of the models' f at the cell centre (sqrt-coordinate centre of
// theta_h, centres of theta_d and phi_d, phi_h = 0: the models are taken as isotropic) and
// 0 where the centre is not a reflection above the surface. Then, in this order:
//  1. per-channel gain error: channel c times g_c = exp(gainSigma z_c), one draw per table;
//  2. multiplicative log-normal noise, mean-preserving: times exp(logSigma z - logSigma^2 / 2),
//     independent per cell and channel (ln of the factor has standard deviation logSigma);
//  3. a signal-dependent noise floor: plus Gaussian noise of standard deviation
//     sqrt(floor^2 + floor f) (read noise floor, plus shot noise that grows as sqrt(f));
//     the result is clamped at 0, since a negative value would mean "missing";
//  4. missing grazing configurations: cells whose centre has wi or wo more than
//     `missingAboveDeg` from the normal are stored as -1 in all channels.
// Every random number is a pure function of (seed, perturbation, cell, channel) (CounterRng),
// so a table is the same however its cells are split between threads.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "materials/bsdf/bsdf.h"
#include "materials/measured/merl_io.h"

namespace scatterlab {

struct MeasurementPerturbation {
  double gainSigma = 0.0;                 // >= 0
  double logSigma = 0.0;                  // >= 0
  double noiseFloor = 0.0;                // >= 0, in sr^-1
  std::optional<double> missingAboveDeg;  // in (0, 90]
  uint64_t seed = 1;

  bool isNone() const { return gainSigma == 0 && logSigma == 0 && noiseFloor == 0 && !missingAboveDeg; }
};

class MeasurementSynthesizer {
 public:
  // The ground truth is the sum of `components` (for a published fit: a Lambertian term and a
  // specular lobe). The models must outlive the synthesizer. Throws std::invalid_argument on
  // a negative sigma or floor or a cut-off outside (0, 90].
  MeasurementSynthesizer(std::vector<const BsdfModel*> components,
                         const MeasurementPerturbation& perturbation);

  // Fills every cell of theta_h cells [begin, end) of `table`; each cell depends only on its
  // index, so disjoint ranges may be filled concurrently.
  void fillThetaHalfCells(int begin, int end, MerlTable& table) const;
  // The whole table, on this thread.
  MerlTable synthesize() const;

  // The ground truth at a cell centre (before any perturbation).
  Rgb groundTruth(size_t cell) const;
  // The per-channel gains this seed draws (1 without gain error).
  const Rgb& channelGains() const { return gains_; }
  const MeasurementPerturbation& perturbation() const { return perturbation_; }

 private:
  std::vector<const BsdfModel*> components_;
  MeasurementPerturbation perturbation_;
  Rgb gains_{1.0};
  double cosMissingAbove_ = -2.0;  // cells with cos(theta_i or theta_o) below it are missing
};

// A standard normal number from two uniforms in [0, 1) (Box & Muller 1958), so that a fixed
// count of draws per cell keeps every cell's numbers independent of the others'.
double standardNormal(double u0, double u1);

}  // namespace scatterlab
