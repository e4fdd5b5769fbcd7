// `scatterlab eval MATERIAL`: the value f (RGB, sr^-1, no cosine) and the sampling density pdf
// (per solid angle of wo) of a material at given direction pairs in its local frame (z =
// normal; materials/bsdf/direction_pairs.h), so that scatterlab's numbers can be compared with
// another renderer's. The pairs come from --directions FILE (a JSON array of {"wi", "wo"}) or
// from --wi THETA,PHI --wo THETA,PHI in degrees. With --samples FILE it prints what sample()
// returns for given incident directions and random numbers instead. Every registry type, measured tables
// included; a subsurface material gives its far-field BRDF (subsurface_far_field_brdf.h).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace scatterlab {

struct EvalCommandOptions {
  std::string material;  // inline JSON, a JSON file, or a measured table
  std::string directionsFile;
  std::string samplesFile;  // sampling queries instead of direction pairs (materials/bsdf/sample_queries.h)
  std::string wi, wo;       // "THETA,PHI" in degrees
  bool json = false;
};

CLI::App* addEvalCommand(CLI::App& app, EvalCommandOptions& options);

// Returns 0; bad input throws MaterialError or InputError (exit 2).
int runEvalCommand(const EvalCommandOptions& options);

}  // namespace scatterlab
