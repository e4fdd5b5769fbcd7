// `scatterlab synth`: measured-style MERL tables from a registry material, from one line of
// a published-fits file, or a whole named bundle into a cache directory, optionally perturbed
// like a measurement (materials/measured/measurement_synthesis.h). Tables are generated in
// parallel (TBB) and are the same bytes for any thread count.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "materials/measured/measurement_synthesis.h"
#include "validation/bsdf_check.h"

namespace scatterlab {

struct SynthCommandOptions {
  std::string material;  // inline JSON or a JSON file; or:
  std::string fitFile;   // with fitName: one line of a published-fits file; or:
  std::string fitName;
  std::optional<std::string> bundle;  // "" for the default cache directory
  std::string out;
  uint64_t seed = 1;
  double gainSigma = 0, logNoise = 0, noiseFloor = 0;
  std::optional<double> missingAboveDeg;
  int threads = 0;  // 0: all cores
  bool force = false;
  bool json = false;
};

CLI::App* addSynthCommand(CLI::App& app, SynthCommandOptions& options);

// Validates every input before any work; bad input throws MaterialError or InputError and
// writes nothing. Returns 0.
int runSynthCommand(const SynthCommandOptions& options);

// The whole table, theta_h cells spread over `threads` TBB workers (0: all cores); `progress`
// (may be empty) hears the fraction done. The result does not depend on `threads`.
MerlTable synthesizeTable(const MeasurementSynthesizer& synthesizer, int threads,
                          const ProgressCallback& progress = {});

}  // namespace scatterlab
