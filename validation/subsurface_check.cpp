#include "validation/subsurface_check.h"

#include <cmath>
#include <cstdio>

#include "materials/core/quadrature.h"
#include "validation/chi_square_images.h"
#include "validation/consistency.h"
#include "validation/radial_chi_square.h"
#include "validation/subsurface_negative_controls.h"

namespace scatterlab {

namespace {

constexpr const char* ChannelNames[3] = {"r", "g", "b"};
// Samples of the per-sample rows (consistency, inverse): deterministic checks, not statistics.
constexpr size_t ConsistencySamples = 100000;

std::string format(const char* fmt, double a, double b = 0, double c = 0) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, fmt, a, b, c);
  return buffer;
}

CheckRow boundRow(const std::string& label, const std::string& test, double statistic, double threshold,
                  std::string note) {
  CheckRow row;
  row.material = label;
  row.test = test;
  row.statistic = statistic;
  row.threshold = threshold;
  row.passed = statistic <= threshold;
  row.note = std::move(note);
  return row;
}

// A control row passes when the kit rejects.
CheckRow controlRow(const std::string& label, const std::string& test, const ChiSquareResult& r) {
  CheckRow row = chiSquareRow(label, test, std::nullopt, r);
  row.passed = !r.passed;
  row.note = (r.passed ? "NOT rejected: the kit cannot see this error; " : "rejected; ") + row.note;
  return row;
}

bool reflects(const RadialProfile& profile, int channel) { return profile.totalReflectance()[channel] > 0; }

// The radius beyond which a channel holds less than 1e-12 of its distribution.
double farRadius(const RadialProfile& profile, int channel) {
  return profile.sampleRadius(channel, 1.0 - 1e-12);
}

double profileEnergy(const RadialProfile& profile, int channel) {
  return integrateAlongQuantiles([&](double r) { return 2.0 * Pi * r * profile.eval(r)[channel]; },
                                 [&](double u) { return profile.sampleRadius(channel, u); });
}

double directionalIntegral(const SeparableBssrdf& bssrdf) {
  QuadratureOptions q;
  q.relativeTolerance = 1e-12;
  q.absoluteTolerance = 1e-15;
  q.minDepth = 4;
  // integral over the hemisphere of Sw(cos) cos dw = 2 pi integral_0^1 Sw(mu) mu dmu.
  return 2.0 * Pi * adaptiveSimpson([&](double mu) { return bssrdf.directional(mu) * mu; }, 0.0, 1.0, q);
}

struct RadiusConsistency {
  double maxPdfError = 0.0, maxWeightError = 0.0, maxInverseError = 0.0;
};

RadiusConsistency radiusConsistency(const RadialProfile& profile, int channel, size_t n, uint64_t seed) {
  RadiusConsistency result;
  const double total = profile.totalReflectance()[channel];
  for (size_t i = 0; i < n; ++i) {
    CounterRng rng(seed, i);
    const double u = rng.uniform();
    const RadiusSample s = sampleRadiusWithWeight(profile, channel, u);
    const double expectedPdf = 2.0 * Pi * s.r * profile.eval(s.r)[channel] / total;
    result.maxPdfError = std::max(result.maxPdfError, consistencyError(s.pdf, expectedPdf));
    result.maxWeightError = std::max(result.maxWeightError, consistencyError(s.weight[channel], total));
    result.maxInverseError = std::max(result.maxInverseError, std::abs(profile.radiusCdf(channel, s.r) - u));
  }
  return result;
}

void maybeWriteImages(const SubsurfaceCheckOptions& options, const std::string& label,
                      const std::string& test, const ChiSquareResult& chi, const std::string& layout) {
  if (options.imageDir && (!options.imagesOnFailureOnly || !chi.passed))
    writeChiSquareImages(*options.imageDir, safeFileStem(label + "_" + test), chi, layout);
}

double threshold(const SubsurfaceCheckOptions& options, const RadialProfile& profile) {
  return sidakSignificance(options.alpha, options.chiSquareTestCount > 0
                                              ? options.chiSquareTestCount
                                              : subsurfaceChiSquareTestCount(profile));
}

}  // namespace

int subsurfaceChiSquareTestCount(const RadialProfile& profile) {
  int count = 2;
  for (int c = 0; c < 3; ++c) count += reflects(profile, c) ? 1 : 0;
  return count;
}

ChiSquareResult radiusChiSquare(const RadialProfile& sampled, const RadialProfile& claimed, int channel,
                                int bins, size_t samples, uint64_t seed, double threshold) {
  RadialChiSquareOptions options;
  options.sampleCount = samples;
  options.seed = seed;
  options.threshold = threshold;
  const std::vector<double> edges =
      equalProbabilityEdges([&](double u) { return claimed.sampleRadius(channel, u); }, bins);
  return radialChiSquareTest(
      [&](CounterRng& rng) -> std::optional<double> { return sampled.sampleRadius(channel, rng.uniform()); },
      [&](double r) { return claimed.radiusPdf(channel, r); }, edges, farRadius(claimed, channel), options);
}

ProbeChiSquareResult probeChiSquare(const ProbeSampler& sampler, const RadialProfile& profile,
                                    ProbeFrame frame, const std::function<double(const Vec2d&)>& pdf,
                                    int rings, int sectors, size_t samples, uint64_t seed, double threshold) {
  const Framed axes = probeFrame(frame);
  const PolarGrid grid = probePolarGrid(sampler, profile, rings, sectors);
  const CellCounts counts = countSamples(grid.cellCount(), samples, seed, [&](CounterRng& rng) {
    const std::optional<Vec2d> p = probeExitOnPlane(sampler, axes, rng);
    if (!p) return CellDraw::failed();
    if (!std::isfinite(p->x) || !std::isfinite(p->y)) return CellDraw{-1, "exit point not finite"};
    if (!(pdf(*p) > 0)) return CellDraw{-1, "exit point found where the pdf is 0"};
    return CellDraw{grid.cellIndex(*p), nullptr};
  });
  ProbeChiSquareResult result;
  const std::vector<double> expected = planarExpectedCounts(pdf, grid, samples);
  result.chiSquare = planarChiSquareVerdict(counts, expected, grid, samples, threshold, 5.0);
  for (double e : expected) result.pdfIntegral += e / double(samples);
  result.hitFraction = 1.0 - double(counts.failed + counts.invalid) / double(samples);
  return result;
}

CheckReport runSubsurfaceChecks(const SeparableBssrdf& bssrdf, const std::string& label,
                                const SubsurfaceCheckOptions& options, const ProgressCallback& progress) {
  const RadialProfile& profile = bssrdf.profile();
  const double alpha = threshold(options, profile);
  const double steps = 5.0;  // three channels, two probe frames
  int step = 0;
  auto report = [&](const std::string& stage) {
    if (progress) progress(stage, step++ / steps);
  };
  CheckReport out;
  const Rgb total = profile.totalReflectance();
  for (int c = 0; c < 3; ++c) {
    const std::string channel = std::string(" (") + ChannelNames[c] + ")";
    report(std::string("radius ") + ChannelNames[c]);
    if (!reflects(profile, c)) {
      out.rows.push_back(boundRow(label, "profile energy" + channel, std::abs(profileEnergy(profile, c)),
                                  ProfileEnergyTolerance,
                                  "the channel reflects nothing: no radius distribution"));
      continue;
    }
    const double energy = profileEnergy(profile, c);
    out.rows.push_back(boundRow(label, "profile energy" + channel, std::abs(energy - total[c]),
                                ProfileEnergyTolerance,
                                format("quadrature %.8f vs closed form %.8f", energy, total[c])));
    const uint64_t seed = deriveSeed(options.seed, uint64_t(c));
    const ChiSquareResult radius =
        radiusChiSquare(profile, profile, c, options.radiusBins, options.samples, seed, alpha);
    out.rows.push_back(chiSquareRow(label, "radius chi2" + channel, std::nullopt, radius));
    maybeWriteImages(options, label, std::string("radius_") + ChannelNames[c], radius,
                     "one row: radius bins equal in the radius CDF, from r = 0 outward");
    const RadiusConsistency consistency =
        radiusConsistency(profile, c, std::min(options.samples, ConsistencySamples), seed);
    out.rows.push_back(
        boundRow(label, "radius consistency" + channel,
                 std::max(consistency.maxPdfError, consistency.maxWeightError), ConsistencyTolerance,
                 format("max pdf error %.2e, max weight error %.2e (pdf vs 2 pi r R / Rd, weight vs Rd)",
                        consistency.maxPdfError, consistency.maxWeightError)));
    out.rows.push_back(boundRow(label, "radius inverse" + channel, consistency.maxInverseError,
                                RadiusInverseTolerance, "max |cdf(sample(u)) - u|"));
  }
  const double directional = directionalIntegral(bssrdf);
  out.rows.push_back(boundRow(
      label, "directional normalisation", std::abs(directional - 1.0), DirectionalNormalisationTolerance,
      format("integral of Ft cos / (pi c) = %.10f, c = %.6f", directional, bssrdf.normalization())));
  const ProbeSampler sampler(profile);
  for (const ProbeFrame frame : {ProbeFrame::Aligned, ProbeFrame::Tilted}) {
    report(std::string("probe ") + toString(frame));
    const Framed axes = probeFrame(frame);
    const ProbeChiSquareResult probe = probeChiSquare(
        sampler, profile, frame, [&](const Vec2d& p) { return probeExitPdfOnPlane(sampler, axes, p); },
        options.probeRings, options.probeSectors, options.samples,
        deriveSeed(options.seed, 10 + uint64_t(frame)), alpha);
    out.rows.push_back(chiSquareRow(label, std::string("probe chi2 (") + toString(frame) + " frame)",
                                    std::nullopt, probe.chiSquare));
    maybeWriteImages(
        options, label, std::string("probe_") + toString(frame), probe.chiSquare,
        "row-major; rows: rings around the entry point from the centre outward (equal in the radial CDF, "
        "with every channel's r_max as an edge); cols: sectors from phi = -pi; last row: its first cell "
        "is the plane beyond the outer ring");
    // The hit rate is binomial: its standard error bounds how well it can match the integral.
    const double standardError =
        std::sqrt(std::max(probe.hitFraction * (1.0 - probe.hitFraction), 1e-12) / double(options.samples));
    out.rows.push_back(
        boundRow(label, std::string("probe normalisation (") + toString(frame) + " frame)",
                 std::abs(probe.pdfIntegral - probe.hitFraction), std::max(1e-3, 4.0 * standardError),
                 format("integral of the pdf %.6f vs fraction of probes that found the plane %.6f",
                        probe.pdfIntegral, probe.hitFraction)));
  }
  if (progress) progress("done", 1.0);
  return out;
}

CheckReport runSubsurfaceNegativeControls(const RadialProfile& profile, const std::string& label,
                                          const SubsurfaceCheckOptions& options,
                                          const ProgressCallback& progress) {
  const double alpha = threshold(options, profile);
  CheckReport out;
  const ProbeSampler sampler(profile);
  const Framed tilted = probeFrame(ProbeFrame::Tilted);
  for (const SubsurfaceControl control : allSubsurfaceControls()) {
    const std::string test = "control: " + toString(control);
    if (progress) progress(test, double(int(control)) / 3.0);
    if (const auto noOp = subsurfaceControlIsNoOp(control, profile, sampler.sampling())) {
      CheckRow row = boundRow(label, test, 0.0, 0.0, "not applicable: " + *noOp);
      out.rows.push_back(row);
      continue;
    }
    const uint64_t seed = deriveSeed(options.seed, 100 + uint64_t(control));
    switch (control) {
      case SubsurfaceControl::RadiusPdfHighOnHalf: {
        const RadiusPdfHighOnHalf broken(profile);
        for (int c = 0; c < 3; ++c)
          if (reflects(profile, c))
            out.rows.push_back(controlRow(label, test + " (" + ChannelNames[c] + ")",
                                          radiusChiSquare(profile, broken, c, options.radiusBins,
                                                          options.samples, seed + uint64_t(c), alpha)));
        break;
      }
      case SubsurfaceControl::WrongChannelWeights: {
        const ProbeSampler claimed(profile, skewedChannelWeights(sampler.sampling()));
        out.rows.push_back(
            controlRow(label, test,
                       probeChiSquare(
                           sampler, profile, ProbeFrame::Tilted,
                           [&](const Vec2d& p) { return probeExitPdfOnPlane(claimed, tilted, p); },
                           options.probeRings, options.probeSectors, options.samples, seed, alpha)
                           .chiSquare));
        break;
      }
      case SubsurfaceControl::RadialShortcut:
        out.rows.push_back(
            controlRow(label, test,
                       probeChiSquare(
                           sampler, profile, ProbeFrame::Tilted,
                           [&](const Vec2d& p) { return radialShortcutPdf(sampler, p); }, options.probeRings,
                           options.probeSectors, options.samples, seed, alpha)
                           .chiSquare));
        break;
    }
  }
  if (progress) progress("done", 1.0);
  return out;
}

}  // namespace scatterlab
