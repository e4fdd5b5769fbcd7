#include "materials/measured/rgl_brdf.h"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "materials/bsdf/metal_reduction.h"

namespace scatterlab {

namespace {

// Grid angles are stored as float32: pi/2 rounds up by 4.4e-8, pi by 8.7e-8.
constexpr double AngleTolerance = 1e-6;
// How far the ends of an anisotropic phi_i grid may sit from the range its reduction covers
// (float32 storage and rounding in the writer, far below any grid step).
constexpr double RangeTolerance = 1e-3;

std::string shapeOf(const TensorField& field) { return field.describe(); }

// The fields of one file, checked one by one with messages naming the file and the field.
class FieldReader {
 public:
  FieldReader(const TensorFile& file, std::string source) : file_(file), source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& problem,
                         const std::string& allowed) const {
    throw TensorFileError(source_ + ": field \"" + field + "\": " + problem + "; allowed: " + allowed);
  }
  [[noreturn]] void failFile(const std::string& problem) const {
    throw TensorFileError(source_ + ": " + problem);
  }

  bool has(const std::string& name) const { return file_.find(name) != nullptr; }

  const TensorField& require(const std::string& name, const std::string& allowed) const {
    const TensorField* field = file_.find(name);
    if (!field) fail(name, "missing", allowed);
    return *field;
  }

  // A floating-point field with `ndim` dimensions; its values as doubles.
  std::vector<double> floats(const TensorField& field, size_t ndim, const std::string& allowed) const {
    if (!isFloatingPoint(field.dtype) || field.shape.size() != ndim)
      fail(field.name, "is " + shapeOf(field), allowed + " (float16, float32 or float64)");
    for (uint64_t extent : field.shape)
      if (extent == 0) fail(field.name, "is " + shapeOf(field) + ", empty", allowed);
    return field.values();
  }

  // A 1-D strictly increasing grid within [lo, hi] (`meaning` says what and in which unit).
  std::vector<double> increasingGrid(const std::string& name, double lo, double hi,
                                     const std::string& meaning) const {
    const std::string allowed =
        "a 1-D array of " + meaning + ", strictly increasing, in [" + fmt(lo) + ", " + fmt(hi) + "]";
    const std::vector<double> grid = floats(require(name, allowed), 1, allowed);
    for (size_t i = 0; i < grid.size(); ++i) {
      if (grid[i] < lo - AngleTolerance || grid[i] > hi + AngleTolerance)
        fail(name, "value " + fmt(grid[i]) + " at index " + std::to_string(i) + " is out of range", allowed);
      if (i > 0 && !(grid[i] > grid[i - 1]))
        fail(name, "does not increase at index " + std::to_string(i), allowed);
    }
    return grid;
  }

  void expectShape(const TensorField& field, const std::vector<uint64_t>& shape,
                   const std::string& allowed) const {
    if (field.shape != shape) fail(field.name, "is " + shapeOf(field), allowed);
  }

  // A warp or table built from a field; the table's own complaint becomes the field's.
  ParametricBilinear2D table(const TensorField& field, std::span<const double> values, size_t channels,
                             std::vector<std::vector<double>> grids, ParametricBilinear2D::Mode mode,
                             const std::string& allowed) const {
    const auto& s = field.shape;
    try {
      return ParametricBilinear2D(values, size_t(s[s.size() - 2]), size_t(s[s.size() - 1]), channels,
                                  std::move(grids), mode);
    } catch (const std::invalid_argument& error) {
      fail(field.name, error.what(), allowed);
    }
  }

  static std::string fmt(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", x);
    return text;
  }

 private:
  const TensorFile& file_;
  std::string source_;
};

// The weights that turn L spectral samples at `wavelengths` into RGB: column l is the RGB of
// the l-th linear-interpolation basis spectrum (metal_reduction.h reflectanceRgb is linear in
// the values, so the RGB of any spectrum is these columns weighted by its samples).
std::vector<Rgb> spectralToRgbWeights(const std::vector<double>& wavelengths) {
  std::vector<Rgb> weights;
  Spectrum basis{wavelengths, std::vector<double>(wavelengths.size(), 0.0)};
  if (wavelengths.size() == 1) {  // a single sample: a constant spectrum
    basis = Spectrum{{wavelengths[0] - 1, wavelengths[0] + 1}, {1.0, 1.0}};
    return {reflectanceRgb(basis)};
  }
  for (size_t l = 0; l < wavelengths.size(); ++l) {
    std::fill(basis.values.begin(), basis.values.end(), 0.0);
    basis.values[l] = 1.0;
    weights.push_back(reflectanceRgb(basis));
  }
  return weights;
}

}  // namespace

RglBrdf::RglBrdf(const TensorFile& file, const std::string& source) {
  const FieldReader r(file, source);
  using Mode = ParametricBilinear2D::Mode;

  const std::vector<double> thetaI =
      r.increasingGrid("theta_i", 0.0, PiOver2, "incident polar angles in radians");
  const std::vector<double> phiI = r.increasingGrid("phi_i", -Pi, Pi, "incident azimuths in radians");
  const uint64_t T = thetaI.size(), P = phiI.size();
  thetaMin_ = thetaI.front();
  thetaMax_ = std::min(thetaI.back(), PiOver2);
  isotropic_ = P <= 2;
  if (!isotropic_) {
    const double span = phiI.back() - phiI.front();
    reduction_ = int(std::lround(2 * Pi / span));
    const std::string allowed =
        "an anisotropic file's phi_i covers [-pi, pi] (reduction 1), [-pi, 0] (reduction 2) or [-pi, -pi/2] "
        "(reduction 4)";
    if (reduction_ != 1 && reduction_ != 2 && reduction_ != 4)
      r.fail("phi_i",
             "covers " + FieldReader::fmt(span) + " radians (reduction " + std::to_string(reduction_) +
                 "), which scatterlab does not read",
             allowed);
    if (reduction_ > 1 && (std::abs(phiI.front() + Pi) > RangeTolerance ||
                           std::abs(phiI.back() - (-Pi + 2 * Pi / reduction_)) > RangeTolerance))
      r.fail("phi_i",
             "covers [" + FieldReader::fmt(phiI.front()) + ", " + FieldReader::fmt(phiI.back()) +
                 "] (reduction " + std::to_string(reduction_) + ") but does not start at -pi",
             allowed);
  }
  const std::vector<std::vector<double>> incident{phiI, thetaI};

  // ndf and sigma: values over the unit square of the half vector and of wi.
  for (const char* name : {"ndf", "sigma"}) {
    const bool isSigma = std::string(name) == "sigma";
    const std::string allowed = std::string("a 2-D array (phi, theta) of at least 2 x 2 ") +
                                (isSigma ? "positive" : "non-negative") + " values";
    const TensorField& field = r.require(name, allowed);
    const std::vector<double> values = r.floats(field, 2, allowed);
    if (field.shape[0] < 2 || field.shape[1] < 2) r.fail(name, "is " + shapeOf(field), allowed);
    for (size_t i = 0; i < values.size(); ++i)
      if (isSigma ? !(values[i] > 0) : !(values[i] >= 0))
        r.fail(name, "value " + FieldReader::fmt(values[i]) + " at flat index " + std::to_string(i), allowed);
    (isSigma ? sigma_ : ndf_) = r.table(field, values, 1, {}, Mode::Values, allowed);
  }

  // The two warps, conditioned on (phi_i, theta_i).
  const std::string incidentShape = "(" + std::to_string(P) + ", " + std::to_string(T) + ", ";
  std::vector<uint64_t> colourGrid;
  for (const char* name : {"vndf", "luminance"}) {
    const std::string allowed =
        "a 4-D array " + incidentShape +
        "rows, columns) of non-negative values, at least 2 x 2 per slice, each slice with "
        "a positive integral";
    const TensorField& field = r.require(name, allowed);
    const std::vector<double> values = r.floats(field, 4, allowed);
    if (field.shape[0] != P || field.shape[1] != T || field.shape[2] < 2 || field.shape[3] < 2)
      r.fail(name, "is " + shapeOf(field), allowed);
    (std::string(name) == "vndf" ? vndf_ : luminance_) =
        r.table(field, values, 1, incident, Mode::Density, allowed);
    if (std::string(name) == "luminance") colourGrid = {field.shape[2], field.shape[3]};
  }

  // Colour: RGB, or spectra reduced to RGB.
  const std::string colourShape = std::to_string(colourGrid[0]) + ", " + std::to_string(colourGrid[1]) + ")";
  std::vector<double> rgb;
  const TensorField* colourField = nullptr;
  if (r.has("rgb") || !r.has("spectra")) {
    const std::string allowed =
        "a 5-D array " + incidentShape + "3, " + colourShape + " (the luminance grid)";
    colourField = &r.require("rgb", allowed + ", or \"spectra\" with \"wavelengths\"");
    rgb = r.floats(*colourField, 5, allowed);
    r.expectShape(*colourField, {P, T, 3, colourGrid[0], colourGrid[1]}, allowed);
  } else {
    const std::vector<double> wavelengths = r.increasingGrid("wavelengths", 0.0, 1e5, "wavelengths in nm");
    const uint64_t L = wavelengths.size();
    const std::string allowed = "a 5-D array " + incidentShape + std::to_string(L) + " (the wavelengths), " +
                                colourShape + " (the luminance grid)";
    colourField = &r.require("spectra", allowed);
    const std::vector<double> spectra = r.floats(*colourField, 5, allowed);
    r.expectShape(*colourField, {P, T, L, colourGrid[0], colourGrid[1]}, allowed);
    std::vector<Rgb> weights;
    try {
      weights = spectralToRgbWeights(wavelengths);
    } catch (const std::runtime_error& error) {
      r.fail("wavelengths", error.what(), "wavelengths in nm overlapping 380-780 nm");
    }
    const size_t cells = size_t(colourGrid[0] * colourGrid[1]);
    rgb.assign(size_t(P * T) * 3 * cells, 0.0);
    for (size_t slice = 0; slice < P * T; ++slice)
      for (size_t l = 0; l < L; ++l)
        for (int c = 0; c < 3; ++c) {
          const double w = weights[l][c];
          const double* in = &spectra[(slice * L + l) * cells];
          double* out = &rgb[(slice * 3 + size_t(c)) * cells];
          for (size_t i = 0; i < cells; ++i) out[i] += w * in[i];
        }
    wavelengthCount_ = L;
  }
  rgb_ = r.table(*colourField, rgb, 3, incident, Mode::Values, "finite values");

  {
    const std::string allowed = "one uint8, 0 or 1 (whether values carry ndf / (4 sigma))";
    const TensorField& field = r.require("jacobian", allowed);
    if (field.dtype != TensorDtype::UInt8 || field.shape != std::vector<uint64_t>{1})
      r.fail("jacobian", "is " + shapeOf(field), allowed);
    const double flag = field.values()[0];
    if (flag != 0 && flag != 1) r.fail("jacobian", "is " + FieldReader::fmt(flag), allowed);
    jacobian_ = flag == 1;
  }
  if (const TensorField* field = file.find("description")) {
    if (field->dtype != TensorDtype::UInt8 || field->shape.size() != 1)
      r.fail("description", "is " + shapeOf(*field), "1-D uint8 text");
    description_.assign(reinterpret_cast<const char*>(field->data.data()), field->data.size());
  }
}

RglBrdf::Fold RglBrdf::foldFor(const Vec3d& wi) const {
  Fold fold;
  if (reduction_ == 2) {
    if (!std::signbit(wi.y)) fold = {-1, -1};  // rotate by pi into phi_i in [-pi, 0]
  } else if (reduction_ == 4) {
    fold.x = std::signbit(wi.x) ? 1 : -1;  // mirror into phi_i in [-pi, -pi/2]
    fold.y = std::signbit(wi.y) ? 1 : -1;
  }
  return fold;
}

RglBrdf::Angles RglBrdf::anglesOf(const Vec3d& wi, const Vec3d& h) const {
  Angles a;
  a.thetaI = std::atan2(std::hypot(wi.x, wi.y), wi.z);
  a.phiI = std::atan2(wi.y, wi.x);
  a.sinThetaH = std::hypot(h.x, h.y);
  const double thetaH = std::atan2(a.sinThetaH, h.z);
  const double phiH = std::atan2(h.y, h.x);
  double uPhi = ((isotropic_ ? phiH - a.phiI : phiH) + Pi) * Inv2Pi;
  uPhi -= std::floor(uPhi);
  a.uWi = {std::sqrt(a.thetaI / PiOver2), (a.phiI + Pi) * Inv2Pi};
  a.uH = {std::sqrt(thetaH / PiOver2), uPhi};
  return a;
}

Rgb RglBrdf::valueAt(const Vec2d& s, const Angles& a, const ParametricBilinear2D::Blend& blend) const {
  Rgb value;
  for (int c = 0; c < 3; ++c) value[c] = std::max(0.0, rgb_.eval(s, blend, size_t(c)));
  if (jacobian_) {
    static const ParametricBilinear2D::Blend Unconditioned = ParametricBilinear2D().blend({});
    value *= ndf_.eval(a.uH, Unconditioned) / (4.0 * sigma_.eval(a.uWi, Unconditioned));
  }
  return value;
}

double RglBrdf::jacobianOf(const Angles& a, const Vec3d& wi, const Vec3d& h) const {
  // d(omega_h) = 2 pi^2 u_theta sin(theta_h) du_theta du_phi; d(omega_o) = 4 (wi . h) d(omega_h).
  return 2.0 * Pi * Pi * a.uH.x * a.sinThetaH * 4.0 * glm::dot(wi, h);
}

Rgb RglBrdf::referenceValue(const Vec3d& wiIn, const Vec3d& woIn) const {
  if (!(wiIn.z > 0) || !(woIn.z > 0)) return Rgb(0.0);
  const Fold fold = foldFor(wiIn);
  const Vec3d wi = fold.apply(wiIn), wo = fold.apply(woIn);
  const Vec3d h = glm::normalize(wi + wo);
  const Angles a = anglesOf(wi, h);
  const double incident[2] = {a.phiI, a.thetaI};
  const auto blend = vndf_.blend(incident);
  return valueAt(vndf_.invert(a.uH, blend).point, a, blend);
}

Rgb RglBrdf::eval(const Vec3d& wi, const Vec3d& wo, TransportMode) const {
  if (!(wi.z > 0) || !(wo.z > 0)) return Rgb(0.0);
  return referenceValue(wi, wo) / wo.z;
}

double RglBrdf::pdf(const Vec3d& wiIn, const Vec3d& woIn, TransportMode) const {
  if (!(wiIn.z > 0) || !(woIn.z > 0)) return 0.0;
  const Fold fold = foldFor(wiIn);
  const Vec3d wi = fold.apply(wiIn), wo = fold.apply(woIn);
  const Vec3d h = glm::normalize(wi + wo);
  const Angles a = anglesOf(wi, h);
  const double incident[2] = {a.phiI, a.thetaI};
  const auto blend = vndf_.blend(incident);
  const auto inverted = vndf_.invert(a.uH, blend);
  const double jacobian = jacobianOf(a, wi, h);
  return jacobian > 0 ? inverted.density * luminance_.eval(inverted.point, blend) / jacobian : 0.0;
}

std::optional<BsdfSample> RglBrdf::sample(const Vec3d& wiIn, double, const Vec2d& u, TransportMode) const {
  if (!(wiIn.z > 0)) return std::nullopt;
  const Fold fold = foldFor(wiIn);
  const Vec3d wi = fold.apply(wiIn);
  Angles a;
  a.thetaI = std::atan2(std::hypot(wi.x, wi.y), wi.z);
  a.phiI = std::atan2(wi.y, wi.x);
  a.uWi = {std::sqrt(a.thetaI / PiOver2), (a.phiI + Pi) * Inv2Pi};
  const double incident[2] = {a.phiI, a.thetaI};
  const auto blend = vndf_.blend(incident);
  // The reference reader feeds (u.y, u.x) to the luminance warp; kept so that the same
  // random numbers give the same directions.
  const auto square = luminance_.sample({u.y, u.x}, blend);
  const auto half = vndf_.sample(square.point, blend);
  a.uH = half.point;
  const double thetaH = sqr(a.uH.x) * PiOver2;
  const double phiH = (2.0 * a.uH.y - 1.0) * Pi + (isotropic_ ? a.phiI : 0.0);
  a.sinThetaH = std::sin(thetaH);
  const Vec3d h = sphericalDirection(a.sinThetaH, std::cos(thetaH), phiH);
  if (!(glm::dot(wi, h) > 0)) return std::nullopt;
  const Vec3d wo = reflect(wi, h);
  if (!(wo.z > 0)) return std::nullopt;
  const double jacobian = jacobianOf(a, wi, h);
  const double pdf = jacobian > 0 ? half.density * square.density / jacobian : 0.0;
  if (!(pdf > 0) || !std::isfinite(pdf)) return std::nullopt;
  // weight = f cos(theta_o) / pdf = value / pdf
  return BsdfSample{fold.apply(wo), valueAt(square.point, a, blend) / pdf, pdf, LobeFlags::GlossyReflection,
                    1.0};
}

std::vector<RglBrdf::TabulatedPair> RglBrdf::tabulatedPairs(size_t* belowHorizon) const {
  const auto& grids = vndf_.parameterGrids();
  const size_t M = luminance_.rows(), N = luminance_.columns();
  std::vector<TabulatedPair> pairs;
  size_t dropped = 0;
  for (size_t p = 0; p < grids[0].size(); ++p)
    for (size_t t = 0; t < grids[1].size(); ++t) {
      const double theta = grids[1][t], phi = grids[0][p];
      if (!(theta < PiOver2 - 1e-6)) continue;
      const Vec3d wi = sphericalDirection(std::sin(theta), std::cos(theta), phi);
      const double incident[2] = {phi, theta};
      const auto blend = vndf_.blend(incident);
      for (size_t r = 0; r < M; ++r)
        for (size_t c = 0; c < N; ++c) {
          const Vec2d uH = vndf_.sample({double(c) / double(N - 1), double(r) / double(M - 1)}, blend).point;
          const double thetaH = sqr(uH.x) * PiOver2;
          const double phiH = (2.0 * uH.y - 1.0) * Pi + (isotropic_ ? phi : 0.0);
          const Vec3d h = sphericalDirection(std::sin(thetaH), std::cos(thetaH), phiH);
          const Vec3d wo = reflect(wi, h);
          if (glm::dot(wi, h) > 0 && wo.z > 0)
            pairs.push_back({wi, wo, p * grids[1].size() + t, r * N + c});
          else
            ++dropped;
        }
    }
  if (belowHorizon) *belowHorizon = dropped;
  return pairs;
}

std::unique_ptr<RglBrdf> readRglBrdf(const std::filesystem::path& path) {
  return std::make_unique<RglBrdf>(readTensorFile(path), "RGL BRDF file \"" + path.string() + "\"");
}

}  // namespace scatterlab
