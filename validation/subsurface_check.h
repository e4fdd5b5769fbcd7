// The kit run on a subsurface material (docs/validation.md section 6), used by `scatterlab check`
// and by the tests: per reflecting channel, the profile's energy (integral of 2 pi r R by
// quadrature against its closed form), the 1-D radius chi-square (bins equal in the CDF),
// per-sample consistency (pdf == 2 pi r R / Rd, weight == Rd) and the inverse CDF round trip;
// the directional term's normalisation; and the 2-D probe chi-square of exit points on a plane
// against the exact multi-axis, multi-channel pdf, with the sampler's frame aligned with the
// plane and tilted against it, plus the probe pdf's normalisation against the hit rate.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "materials/bssrdf/separable_bssrdf.h"
#include "validation/bsdf_check.h"
#include "validation/check_report.h"
#include "validation/probe_plane.h"

namespace scatterlab {

struct SubsurfaceCheckOptions {
  size_t samples = 1'000'000;  // per chi-square test
  int radiusBins = 64;
  int probeRings = 32;
  int probeSectors = 32;
  uint64_t seed = 1;
  double alpha = 0.01;         // family-wise, Sidak-corrected over every chi-square test
  int chiSquareTestCount = 0;  // tests in the whole suite; 0: this run's count
  // Observed / expected / residual maps and tables of every chi-square test (chi_square_images.h).
  std::optional<std::filesystem::path> imageDir;
  bool imagesOnFailureOnly = false;
};

// Tolerances of the deterministic rows.
inline constexpr double ProfileEnergyTolerance = 1e-4;   // |quadrature - closed form|
inline constexpr double RadiusInverseTolerance = 1e-10;  // |F(r(u)) - u|
inline constexpr double DirectionalNormalisationTolerance = 1e-6;

// Chi-square tests runSubsurfaceChecks performs: one per reflecting channel, two probe tests.
int subsurfaceChiSquareTestCount(const RadialProfile& profile);

CheckReport runSubsurfaceChecks(const SeparableBssrdf& bssrdf, const std::string& label,
                                const SubsurfaceCheckOptions& options, const ProgressCallback& progress = {});

// The controls of subsurface_negative_controls.h; a row PASSES when the kit REJECTS the broken
// sampler (or, with a note, when the control cannot differ for this profile).
CheckReport runSubsurfaceNegativeControls(const RadialProfile& profile, const std::string& label,
                                          const SubsurfaceCheckOptions& options,
                                          const ProgressCallback& progress = {});

// ---- The kit functions the rows are made of (the tests call them directly) ----

// Radii drawn from `sampled` (channel c) against `claimed`'s radius pdf, in `bins` bins equal
// in claimed's CDF.
ChiSquareResult radiusChiSquare(const RadialProfile& sampled, const RadialProfile& claimed, int channel,
                                int bins, size_t samples, uint64_t seed, double threshold);

struct ProbeChiSquareResult {
  ChiSquareResult chiSquare;
  double pdfIntegral = 0.0;  // integral of the claimed pdf over the plane
  double hitFraction = 0.0;  // probes that found the plane
};
// Exit points of `sampler`'s probes (frame `frame`) on the plane, against `pdf` per unit area;
// a found point where pdf is 0 is an invalid sample.
ProbeChiSquareResult probeChiSquare(const ProbeSampler& sampler, const RadialProfile& profile,
                                    ProbeFrame frame, const std::function<double(const Vec2d&)>& pdf,
                                    int rings, int sectors, size_t samples, uint64_t seed, double threshold);

}  // namespace scatterlab
