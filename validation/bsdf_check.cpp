#include "validation/bsdf_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "validation/bsdf_sampling.h"
#include "validation/chi_square_images.h"
#include "validation/consistency.h"
#include "validation/energy.h"
#include "validation/negative_controls.h"
#include "validation/reciprocity.h"
#include "validation/transport_modes.h"

namespace scatterlab {
namespace {

// Albedo from quadrature must not exceed 1 by more than the quadrature's own error.
constexpr double AlbedoTolerance = 1e-4;
// White furnace (docs/validation.md section 3): a lossless model's albedo is 1 within what the
// model states it is accurate to (BsdfModel::losslessAccuracy: 0 when exact by construction,
// a table's error otherwise) plus the quadrature's own error: its error estimate (a Richardson
// difference summed over the cells: the size of the error, not a strict bound, so counted
// twice) and the round-off of summing the cells in double precision.
constexpr double FurnaceQuadratureErrors = 2.0;
constexpr double FurnaceRoundOff = 1e-9;
// Quadrature vs importance-sampled albedo: |difference| <= 5 standard errors (+ a floor for
// the quadrature's error, which matters when the weight has zero variance, e.g. Lambertian).
constexpr double AlbedoAgreementSigmas = 5.0;
constexpr double AlbedoQuadratureFloor = 2e-5;

std::string format(const char* fmt, double a, double b = 0, double c = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b, c);
  return buf;
}

std::string fileStem(const std::string& label, double wiTheta) {
  return safeFileStem(label) + "_wi" + format("%g", wiTheta);
}

CheckRow makeRow(const std::string& label, const std::string& test, double wiTheta, double statistic,
                 double threshold, bool passed, std::string note) {
  CheckRow row;
  row.material = label;
  row.test = test;
  row.wiThetaDeg = wiTheta;
  row.statistic = statistic;
  row.threshold = threshold;
  row.passed = passed;
  row.note = std::move(note);
  return row;
}

// Values no model may return, counted: drawn samples whose weight or pdf is not finite or
// negative, and cells whose integral of pdf is not finite or negative, or of f |cos| not finite
// (eval or pdf went wrong at some quadrature point; a negative eval shows in the albedo rows,
// where the Richardson-corrected quadrature of a narrow lobe may also dip a hair below 0).
// Any of them fails the row; other rows fail or mislead too, but only this one counts them.
CheckRow invalidValuesRow(const std::string& label, double wiTheta, const SampleHistogram& histogram,
                          const std::vector<glm::dvec4>& cells) {
  size_t badCells = 0;
  for (const glm::dvec4& c : cells)
    badCells +=
        !(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w) && c.x >= 0);
  const size_t bad = histogram.invalidSamples + badCells;
  std::string note = std::to_string(histogram.invalidSamples) + " of " +
                     std::to_string(histogram.sampleCount) +
                     " drawn samples with a weight or pdf that is not finite or negative; " +
                     std::to_string(badCells) + " of " + std::to_string(cells.size()) +
                     " cells whose integral of pdf is not finite or negative, or of f |cos| not finite";
  if (!histogram.firstInvalid.empty()) note += "; first sample: " + histogram.firstInvalid;
  return makeRow(label, "invalid values", wiTheta, double(bad), 0.0, bad == 0, note);
}

double perTestThreshold(const BsdfCheckOptions& options, int runCount) {
  return sidakSignificance(options.alpha,
                           options.chiSquareTestCount > 0 ? options.chiSquareTestCount : runCount);
}

QuadratureOptions kitQuadrature(size_t samples) {
  QuadratureOptions q;
  // Absolute floor: a thousandth of one expected sample, per cell.
  q.absoluteTolerance = 1e-3 / double(std::max<size_t>(samples, 1));
  return q;
}

bool hasTransmission(const BsdfModel& model) { return hasAny(model.flags(), LobeFlags::Transmission); }

CheckRow consistencyRow(const std::string& label, const std::string& test, double wiTheta,
                        const ConsistencyResult& consistency, size_t n) {
  std::string note = format("%.0f samples, max weight error %.2e, max pdf error %.2e", double(n),
                            consistency.maxWeightError, consistency.maxPdfError);
  if (consistency.supportViolations)
    note = std::to_string(consistency.supportViolations) + " of " +
           std::to_string(consistency.supportProbes) + " directions have eval > 0 but pdf = 0; " + note;
  if (!consistency.firstFailure.empty()) note += "; first failure: " + consistency.firstFailure;
  return makeRow(label, test, wiTheta, std::max(consistency.maxWeightError, consistency.maxPdfError),
                 ConsistencyTolerance, consistency.passed(), note);
}

CheckReport checkAtIncidentAngle(const BsdfModel& model, const std::string& label,
                                 const BsdfCheckOptions& options, double wiTheta, uint64_t seed,
                                 double threshold) {
  const Vec3d wi = directionFromDegrees(wiTheta, options.wiPhiDeg);
  const SphericalGrid grid{options.thetaBins, options.phiBins};
  const size_t n = options.samples;
  // Energy rows need importance transport through refractions (energyTransportMode says why).
  // The histogram is drawn in that mode too, since its delta directions carry the weights
  // that enter the albedo; the directions themselves do not depend on the mode (the
  // "transport modes" row checks that).
  const bool transmission = hasTransmission(model);
  const TransportMode mode = energyTransportMode(model);
  CheckReport report;

  const SampleHistogram histogram = drawSamples(grid, bsdfDirectionSampler(model, wi, mode), n, seed);

  // Weights must match eval |cos| / pdf in whichever mode a caller uses: with transmission,
  // both modes are checked, and how they relate. The second mode's checks are per-sample
  // identities (no statistics, no albedo estimate), so a quarter of the samples is enough.
  // These per-sample checks run before the quadrature (they need nothing from it): a model
  // answered in rounds (a Python object, python/src/replayed_bsdf.h) then knows every value at
  // the sampled directions when its quadrature runs, and integrates once.
  const ConsistencyResult consistency =
      checkConsistency(model, wi, grid, n, seed, DefaultSupportProbes, mode);
  const size_t nModes = std::max<size_t>(n / 4, std::min<size_t>(n, 10000));
  std::optional<ConsistencyResult> radiance;
  std::optional<TransportModesResult> modes;
  if (transmission) {
    radiance = checkConsistency(model, wi, grid, nModes, seed, DefaultSupportProbes, TransportMode::Radiance);
    modes = checkTransportModes(model, wi, nModes, seed);
  }

  const CellIntegrals<glm::dvec4> integrals =
      integrateEnergyCells(model, wi, mode, grid, histogram.probes, kitQuadrature(n));
  const std::vector<glm::dvec4>& cells = integrals.values;
  const ChiSquareResult chi = chiSquareVerdict(histogram, pdfPart(cells), grid, n, threshold);
  report.rows.push_back(chiSquareRow(label, "chi2", wiTheta, chi));
  report.rows.push_back(invalidValuesRow(label, wiTheta, histogram, cells));

  report.rows.push_back(consistencyRow(label, transmission ? "consistency (importance)" : "consistency",
                                       wiTheta, consistency, n));
  if (transmission) {
    report.rows.push_back(consistencyRow(label, "consistency (radiance)", wiTheta, *radiance, nModes));
    std::string note = format(
        "%.0f samples: same wo, pdf, lobe; eta = n(wo)/n(wi); radiance weight = importance "
        "weight / eta^2 (max error %.2e)",
        double(nModes), modes->maxWeightError);
    if (!modes->firstFailure.empty())
      note = std::to_string(modes->violations) + " violations, first: " + modes->firstFailure + "; " + note;
    report.rows.push_back(makeRow(label, "transport modes", wiTheta, modes->maxWeightError,
                                  ConsistencyTolerance, modes->passed(), note));
  }

  const EnergyResult energy = energyFromIntegrals(cells, integrals.errors, histogram);
  const bool quadratureResolved = energy.pdfIntegralError <= NormalisationQuadratureLimit;
  report.rows.push_back(
      makeRow(label, "normalisation", wiTheta, energy.normalisationError, energy.normalisationTolerance,
              quadratureResolved && energy.normalisationError <= energy.normalisationTolerance,
              format("integral of pdf %.8f (quadrature error estimate %.1e)", energy.pdfIntegral,
                     energy.pdfIntegralError) +
                  format(" + delta %.8f vs 1 - P(fail) = %.8f", energy.deltaProbability,
                         1.0 - energy.failureProbability) +
                  (quadratureResolved ? "" : "; the quadrature did not resolve the pdf")));

  const double maxAlbedo = std::max({energy.albedo.x, energy.albedo.y, energy.albedo.z});
  const std::string quadratureMode =
      transmission ? "quadrature + deltas, importance transport" : "quadrature";
  report.rows.push_back(
      makeRow(label, "albedo", wiTheta, maxAlbedo, 1.0 + AlbedoTolerance, maxAlbedo <= 1.0 + AlbedoTolerance,
              "directional albedo (" + quadratureMode + ")" +
                  format(" r %.5f g %.5f b %.5f", energy.albedo.x, energy.albedo.y, energy.albedo.z) +
                  (model.isLossless() ? "" : format(", loses %.2f%% at least", 100 * (1 - maxAlbedo)))));

  double worstZ = 0;
  for (int c = 0; c < 3; ++c) {
    const double z = std::abs(energy.albedo[c] - consistency.albedoMean[c]) /
                     (consistency.albedoStdError[c] + AlbedoQuadratureFloor);
    worstZ = std::max(worstZ, std::isfinite(z) ? z : INFINITY);
  }
  report.rows.push_back(
      makeRow(label, "albedo-mc", wiTheta, worstZ, AlbedoAgreementSigmas, worstZ <= AlbedoAgreementSigmas,
              format("importance-sampled albedo r %.5f g %.5f b %.5f (|z| vs quadrature)",
                     consistency.albedoMean.x, consistency.albedoMean.y, consistency.albedoMean.z)));

  if (model.isLossless()) {
    const double deviation = std::max(
        {std::abs(energy.albedo.x - 1), std::abs(energy.albedo.y - 1), std::abs(energy.albedo.z - 1)});
    const double quadratureError =
        std::max({energy.albedoError.x, energy.albedoError.y, energy.albedoError.z});
    const double limit =
        model.losslessAccuracy() + FurnaceQuadratureErrors * quadratureError + FurnaceRoundOff;
    report.rows.push_back(makeRow(
        label, "furnace", wiTheta, deviation, limit, deviation <= limit,
        format("lossless model: |albedo - 1| per channel; limit = model accuracy %.1e + 2 x quadrature "
               "error estimate %.1e + 1e-9",
               model.losslessAccuracy(), quadratureError)));
  }

  if (options.imageDir && (!options.imagesOnFailureOnly || !report.passed()))
    writeChiSquareImages(*options.imageDir, fileStem(label, wiTheta), chi,
                         "row-major; rows: cos(theta) from -1 to 1; cols: phi from -pi to pi",
                         &consistency.maxErrorPerCell, ConsistencyTolerance);
  return report;
}

}  // namespace

std::vector<double> incidentAngles(const BsdfCheckOptions& options, const BsdfModel& model) {
  std::vector<double> angles = options.wiThetaDeg;
  if (!options.transmissionFromBelow || !hasTransmission(model)) return angles;
  for (const double theta : options.wiThetaDeg) {
    const double below = 180.0 - theta;
    if (theta < 90.0 && std::find(angles.begin(), angles.end(), below) == angles.end())
      angles.push_back(below);
  }
  return angles;
}

int chiSquareTestCount(const BsdfCheckOptions& options) { return int(options.wiThetaDeg.size()); }

int chiSquareTestCount(const BsdfCheckOptions& options, const BsdfModel& model) {
  return int(incidentAngles(options, model).size());
}

CheckReport runBsdfChecksAtAngle(const BsdfModel& model, const std::string& label,
                                 const BsdfCheckOptions& options, size_t angleIndex) {
  const std::vector<double> angles = incidentAngles(options, model);
  return checkAtIncidentAngle(model, label, options, angles.at(angleIndex),
                              deriveSeed(options.seed, angleIndex),
                              perTestThreshold(options, int(angles.size())));
}

CheckReport runReciprocityChecks(const BsdfModel& model, const std::string& label,
                                 const BsdfCheckOptions& options) {
  CheckReport report;
  // Through a refraction the relation depends on the transport mode (reciprocity.h): models
  // with transmission get all three forms, each a row.
  struct Relation {
    const char* test;
    ReciprocityRelation relation;
    const char* what;
  };
  std::vector<Relation> relations{{"reciprocity", ReciprocityRelation::Radiance, "f(wi,wo) = f(wo,wi)"}};
  if (hasTransmission(model))
    relations = {
        {"reciprocity (radiance)", ReciprocityRelation::Radiance, "f(wi,wo)/n(wi)^2 = f(wo,wi)/n(wo)^2"},
        {"reciprocity (importance)", ReciprocityRelation::Importance, "f(wi,wo)/n(wo)^2 = f(wo,wi)/n(wi)^2"},
        {"adjoint", ReciprocityRelation::Adjoint, "f(wi,wo,radiance) = f(wo,wi,importance)"}};
  // A model made of delta lobes has eval = 0 for every pair: the rows pass trivially, and say so.
  const bool deltaOnly = !hasAny(model.flags(), LobeFlags::Diffuse | LobeFlags::Glossy);
  for (const Relation& relation : relations) {
    CheckRow row;
    row.material = label;
    row.test = relation.test;
    row.threshold = ReciprocityTolerance;
    if (model.isReciprocal()) {
      const ReciprocityResult r =
          checkReciprocity(model, size_t(options.reciprocityPairs), deriveSeed(options.seed, 1000),
                           model.interiorIndex(), relation.relation);
      row.statistic = r.maxError;
      row.passed = r.passed();
      row.note = std::string(relation.what) + " on " + std::to_string(r.pairs) +
                 " random pairs over the sphere" +
                 (deltaOnly ? " (delta lobes only: eval is 0 everywhere, nothing to compare)" : "") +
                 (r.worst.empty() ? "" : "; " + r.worst);
    } else {
      row.passed = true;
      row.note = "not reciprocal by design (listed, not tested)";
    }
    report.rows.push_back(row);
  }
  return report;
}

CheckReport runBsdfChecks(const BsdfModel& model, const std::string& label, const BsdfCheckOptions& options,
                          const ProgressCallback& progress) {
  CheckReport report;
  const std::vector<double> angles = incidentAngles(options, model);
  const size_t steps = angles.size() + 1;
  for (size_t k = 0; k < angles.size(); ++k) {
    if (progress) progress(label + ": wi " + format("%g", angles[k]) + " deg", double(k) / steps);
    report.append(runBsdfChecksAtAngle(model, label, options, k));
  }
  if (progress) progress(label + ": reciprocity", double(steps - 1) / steps);
  report.append(runReciprocityChecks(model, label, options));
  if (progress) progress(label + ": done", 1.0);
  return report;
}

CheckReport runNegativeControl(const BsdfModel& model, const BsdfModel* alteredSampler,
                               const std::string& label, const BsdfCheckOptions& options,
                               NegativeControl control, size_t angleIndex) {
  CheckReport report;
  const std::string test = "control: " + toString(control);
  if (control == NegativeControl::RoughnessMismatch && !alteredSampler) {
    CheckRow row;
    row.material = label;
    row.test = test;
    row.passed = true;
    row.note = "not applicable: the model has no lobe-width parameter";
    report.rows.push_back(row);
    return report;
  }
  const std::vector<double> angles = incidentAngles(options, model);
  const double wiTheta = angles.at(angleIndex);
  const Vec3d wi = directionFromDegrees(wiTheta, options.wiPhiDeg);
  const std::unique_ptr<BsdfModel> broken = makeNegativeControl(control, model, wi, alteredSampler);
  if (const std::optional<std::string> noOp = negativeControlIsNoOp(control, model, *broken, wi)) {
    CheckRow row;
    row.material = label;
    row.test = test;
    row.wiThetaDeg = wiTheta;
    row.passed = true;
    row.note = *noOp;
    report.rows.push_back(row);
    return report;
  }
  ChiSquareOptions chiOptions;
  chiOptions.grid = SphericalGrid{options.thetaBins, options.phiBins};
  chiOptions.sampleCount = options.samples;
  chiOptions.seed = deriveSeed(options.seed, angleIndex);
  chiOptions.threshold = perTestThreshold(options, int(angles.size()));
  chiOptions.quadrature = kitQuadrature(options.samples);
  // bsdfChiSquareTest, with the pdf integrated in bulk for a model that answers in bulk.
  const TransportMode mode = energyTransportMode(model);
  const SampleHistogram histogram = drawSamples(chiOptions.grid, bsdfDirectionSampler(*broken, wi, mode),
                                                chiOptions.sampleCount, chiOptions.seed);
  const std::vector<double> integrals =
      integratePdfCells(*broken, wi, mode, chiOptions.grid, histogram.probes, chiOptions.quadrature).values;
  const ChiSquareResult r = chiSquareVerdict(histogram, integrals, chiOptions.grid, chiOptions.sampleCount,
                                             chiOptions.threshold, chiOptions.minExpected);
  CheckRow row = chiSquareRow(label, test, wiTheta, r);
  // This row passes when the kit rejects the broken sampler.
  row.passed = !r.passed;
  row.note = (r.passed ? "NOT rejected: the kit cannot see this error here" : "rejected") +
             (r.failure.empty() ? std::string() : " (" + r.failure + ")");
  report.rows.push_back(row);
  return report;
}

CheckReport runNegativeControls(const BsdfModel& model, const BsdfModel* alteredSampler,
                                const std::string& label, const BsdfCheckOptions& options,
                                const ProgressCallback& progress) {
  CheckReport report;
  const std::vector<double> angles = incidentAngles(options, model);
  const auto controls = allNegativeControls();
  for (size_t c = 0; c < controls.size(); ++c) {
    // A control that does not apply is one row, whatever the angles.
    const size_t angleCount =
        controls[c] == NegativeControl::RoughnessMismatch && !alteredSampler ? 1 : angles.size();
    for (size_t k = 0; k < angleCount; ++k) {
      if (progress)
        progress(label + ": control: " + toString(controls[c]) +
                     (k < angles.size() ? " wi " + format("%g", angles[k]) : std::string()),
                 double(c * angles.size() + k) / double(controls.size() * angles.size()));
      report.append(runNegativeControl(model, alteredSampler, label, options, controls[c], k));
    }
  }
  return report;
}

}  // namespace scatterlab
