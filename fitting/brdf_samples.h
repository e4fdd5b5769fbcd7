// The data a BRDF fit compares with: measured values f (sr^-1, linear RGB) at direction pairs,
// each with a sampling weight.
//
// From a MERL table (samplesFromMerl): every usable cell, at its centre (sqrt-coordinate
// centre of theta_h, centres of theta_d and phi_d, phi_h = 0, exactly where
// MeasurementSynthesizer tabulates, so a noise-free table of a model is that model at the
// samples). A cell is usable when it is measured (no channel negative: missing measurements
// are excluded, never filled in) and its centre is a reflection above the surface. Weight 1.
//
// From an RGL file (samplesFromRgl): the file's own samples, the pairs it tabulates
// (RglBrdf::tabulatedPairs): at each incident direction of its grid above the surface, every
// node of its colour grid mapped through the file's vndf warp to wo, with the BRDF there (the
// stored colour itself). Weight 1 each, as a MERL cell: the file's warp places its nodes
// densely where the reflectance is, as MERL's theta_h cells crowd the highlight; pairs whose
// wo falls below the horizon are counted, not used. Strata: one per incident direction and
// colour-grid row.
//
// Subsets (stratifiedSubset): the strata are the (theta_h, theta_d) cells, 180 phi_d cells
// each. In a stratum with n samples, k = ceil(n * target / total) are chosen without
// replacement (a partial Fisher-Yates shuffle driven by CounterRng(seed, stratum)) and each
// is weighted n / k, so that weighted sums over the subset are unbiased estimates of the
// sums over the whole set; every stratum keeps at least one sample, so a sharp highlight
// (the first theta_h rows) is never skipped. The same seed gives the same subset.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "materials/core/math.h"
#include "materials/measured/merl_io.h"
#include "materials/measured/rgl_brdf.h"

namespace scatterlab::fitting {

struct BrdfSamples {
  std::vector<Vec3d> wi, wo;
  std::vector<Rgb> value;
  std::vector<double> weight;
  // Samples of one stratum are stored next to each other; stratum ids increase.
  std::vector<uint32_t> stratum;

  size_t size() const { return value.size(); }
  bool empty() const { return value.empty(); }
  void add(const Vec3d& in, const Vec3d& out, const Rgb& f, double w, uint32_t s) {
    wi.push_back(in);
    wo.push_back(out);
    value.push_back(f);
    weight.push_back(w);
    stratum.push_back(s);
  }
  void reserve(size_t n);
  // The weights' sum: the number of samples the set stands for.
  double totalWeight() const;
};

struct MerlSampleCounts {
  size_t cells = 0, missing = 0, unreachable = 0, usable = 0;
};

// Every usable cell of `table` (see above); `counts` (optional) says how many were dropped.
BrdfSamples samplesFromMerl(const MerlTable& table, MerlSampleCounts* counts = nullptr);

struct RglSampleCounts {
  size_t nodes = 0, belowHorizon = 0, usable = 0;
};

BrdfSamples samplesFromRgl(const RglBrdf& brdf, RglSampleCounts* counts = nullptr);

// A stratified subset of about `target` samples (see above); a copy of `samples` when
// target is 0 or not below its size.
BrdfSamples stratifiedSubset(const BrdfSamples& samples, size_t target, uint64_t seed);

}  // namespace scatterlab::fitting
