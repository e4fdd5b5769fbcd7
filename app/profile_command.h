// `scatterlab profile`: a subsurface material's radial profile per channel — R(r) averaged over
// annuli of a radius grid and the total diffuse reflectance — and, with --reference walk, the
// same from the half-space random walk (materials/bssrdf/half_space_walk.h) with standard
// errors, so a diffusion profile can be read next to its ground truth. With --compare, every
// model on the material's medium against the walk in one table (validation/profile_comparison.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace scatterlab {

struct ProfileCommandOptions {
  std::string material;          // inline JSON or a file
  std::string reference;         // "" or "walk"
  std::vector<double> albedo;    // walk: single-scattering albedo, 1 or 3 values (default: the medium's)
  std::optional<double> eta, g;  // walk: boundary index and HG g (default: the material's)
  uint64_t paths = 1'000'000;    // walk: paths per channel
  std::optional<double> minRadius, maxRadius;  // mm; default: from the profile
  int bins = 24;
  uint64_t seed = 1;
  int threads = 0;
  bool compare = false;  // every model against the walk (needs --reference walk)
  bool json = false;
};

CLI::App* addProfileCommand(CLI::App& app, ProfileCommandOptions& options);

// Validates everything before any work; bad input throws MaterialError or InputError.
int runProfileCommand(const ProfileCommandOptions& options);

// The document --json prints (with --compare, the comparison's), validated and computed as the
// command does, printing nothing but the progress line (with `progress`). Walk paths that stopped
// being finite are counted in it ("non_finite_paths"), not reported. The Python package's
// sl.profile (docs/python.md).
nlohmann::json profileReport(const ProfileCommandOptions& options, bool progress);

}  // namespace scatterlab
