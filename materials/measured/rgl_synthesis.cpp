#include "materials/measured/rgl_synthesis.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "materials/core/parametric_bilinear_2d.h"

namespace scatterlab {

namespace {

using Mode = ParametricBilinear2D::Mode;

constexpr double FloorFraction = 0.01;  // of a density's mean, so that no region has none

double toFloat32(double x) { return double(float(x)); }

std::vector<double> roundedToFloat32(std::vector<double> values) {
  for (double& v : values) v = toFloat32(v);
  return values;
}

// A triangle wave over the azimuth's unit coordinate: 0 at phi = -pi and pi (periodic), 1 at
// phi = 0; linear between, so bilinear interpolation reproduces it when u_phi = 0.5 is a row.
double triangle(double uPhi) { return 1.0 - std::abs(2.0 * uPhi - 1.0); }

// The positive functions the file stores as ndf and sigma: one value at the pole (u_theta =
// 0), periodic in azimuth, and piecewise bilinear on the grid, so that interpolation
// reproduces them everywhere. An isotropic file's sigma does not depend on wi's azimuth.
double syntheticNdf(const Vec2d& u, bool) { return 0.5 + u.x * (1.0 + 0.5 * triangle(u.y)); }
double syntheticSigma(const Vec2d& u, bool isotropic) {
  return 0.3 + u.x * (0.2 + (isotropic ? 0.0 : 0.1 * triangle(u.y)));
}

// A function tabulated on a rows x columns grid of the unit square (x along columns), float32.
std::vector<double> tabulate(size_t rows, size_t columns, bool isotropic, double (*f)(const Vec2d&, bool)) {
  if (rows % 2 == 0) throw std::invalid_argument("the ndf and sigma grids need an odd number of rows");
  std::vector<double> values(rows * columns);
  for (size_t r = 0; r < rows; ++r)
    for (size_t c = 0; c < columns; ++c)
      values[r * columns + c] =
          toFloat32(f({double(c) / double(columns - 1), double(r) / double(rows - 1)}, isotropic));
  return values;
}

Vec2d gridPoint(size_t row, size_t column, size_t resolution) {
  return {double(column) / double(resolution - 1), double(row) / double(resolution - 1)};
}

Vec2d unitOfDirection(const Vec3d& w) {
  const double theta = std::atan2(std::hypot(w.x, w.y), w.z), phi = std::atan2(w.y, w.x);
  return {std::sqrt(theta / PiOver2), (phi + Pi) * Inv2Pi};
}

// The half vector at unit coordinates u (for an isotropic file, azimuth relative to phiI).
Vec3d halfVector(const Vec2d& u, double phiI, bool isotropic) {
  const double theta = sqr(u.x) * PiOver2;
  const double phi = (2.0 * u.y - 1.0) * Pi + (isotropic ? phiI : 0.0);
  return sphericalDirection(std::sin(theta), std::cos(theta), phi);
}

// wo = reflect(wi, h) when it is a reflection above the surface.
std::optional<Vec3d> reflected(const Vec3d& wi, const Vec3d& h) {
  if (!(wi.z > 0) || !(glm::dot(wi, h) > 0)) return std::nullopt;
  const Vec3d wo = reflect(wi, h);
  return wo.z > 0 ? std::optional<Vec3d>(wo) : std::nullopt;
}

void addFloor(std::vector<double>& density) {
  const double mean = std::accumulate(density.begin(), density.end(), 0.0) / double(density.size());
  for (double& v : density) v = mean > 0 ? v + FloorFraction * mean : 1.0;
}

std::vector<double> fieldGrid(const TensorFile& file, const char* name) {
  const TensorField* field = file.find(name);
  if (!field) throw std::invalid_argument(std::string("tensor file without \"") + name + "\"");
  return field->values();
}

// One slice of the file's vndf as the reader builds it (float32 values, this slice alone).
ParametricBilinear2D vndfSlice(const TensorFile& file, size_t phiIndex, size_t thetaIndex) {
  const TensorField* vndf = file.find("vndf");
  if (!vndf) throw std::invalid_argument("tensor file without \"vndf\"");
  const size_t rows = size_t(vndf->shape[2]), columns = size_t(vndf->shape[3]);
  const std::vector<double> all = vndf->values();
  const size_t offset = (phiIndex * size_t(vndf->shape[1]) + thetaIndex) * rows * columns;
  return ParametricBilinear2D(std::span<const double>(all).subspan(offset, rows * columns), rows, columns, 1,
                              {}, Mode::Density);
}

}  // namespace

RglChannelValues modelChannels(const BsdfModel& model) {
  return {[&model](const Vec3d& wi, const Vec3d& wo, std::span<double> channels) {
            const Rgb f = model.eval(wi, wo) * wo.z;
            for (int c = 0; c < 3; ++c) channels[size_t(c)] = f[c];
          },
          [](std::span<const double> c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }};
}

Vec3d gridIncident(const TensorFile& file, size_t phiIndex, size_t thetaIndex) {
  const double theta = fieldGrid(file, "theta_i").at(thetaIndex), phi = fieldGrid(file, "phi_i").at(phiIndex);
  return sphericalDirection(std::sin(theta), std::cos(theta), phi);
}

std::optional<Vec3d> sampledOutgoing(const TensorFile& file, size_t phiIndex, size_t thetaIndex, size_t row,
                                     size_t column) {
  const size_t resolution = size_t(file.find("luminance")->shape[2]);
  const Vec3d wi = gridIncident(file, phiIndex, thetaIndex);
  const ParametricBilinear2D warp = vndfSlice(file, phiIndex, thetaIndex);
  const Vec2d uH = warp.sample(gridPoint(row, column, resolution), warp.blend({})).point;
  return reflected(wi, halfVector(uH, std::atan2(wi.y, wi.x), fieldGrid(file, "phi_i").size() <= 2));
}

TensorFile synthesizeRglFile(const RglChannelValues& values, const RglSynthesisOptions& o) {
  const bool spectral = !o.wavelengths.empty();
  const size_t channels = spectral ? o.wavelengths.size() : 3;
  const size_t P = o.phiI.size(), T = o.thetaI.size(), N = o.vndfResolution, M = o.colourResolution;
  const bool isotropic = P <= 2;
  const std::vector<double> phiI = roundedToFloat32(o.phiI), thetaI = roundedToFloat32(o.thetaI);

  TensorFile file;
  file.set(TensorField::fromValues("version", TensorDtype::UInt32, {2}, std::vector<double>{1, 0}));
  file.set(TensorField::fromText("description", o.description));
  file.set(TensorField::fromValues("phi_i", TensorDtype::Float32, {P}, phiI));
  file.set(TensorField::fromValues("theta_i", TensorDtype::Float32, {T}, thetaI));
  const std::vector<double> sigma = tabulate(o.ndfRows, o.ndfColumns, isotropic, syntheticSigma);
  const std::vector<double> ndf = tabulate(o.ndfRows, o.ndfColumns, isotropic, syntheticNdf);
  file.set(TensorField::fromValues("sigma", TensorDtype::Float32, {o.ndfRows, o.ndfColumns}, sigma));
  file.set(TensorField::fromValues("ndf", TensorDtype::Float32, {o.ndfRows, o.ndfColumns}, ndf));
  const ParametricBilinear2D sigmaTable(sigma, o.ndfRows, o.ndfColumns, 1, {}, Mode::Values);
  const ParametricBilinear2D ndfTable(ndf, o.ndfRows, o.ndfColumns, 1, {}, Mode::Values);
  const auto unconditioned = ndfTable.blend({});

  std::vector<double> vndf(P * T * N * N), luminance(P * T * M * M), colour(P * T * channels * M * M);
  std::vector<double> value(channels);
  for (size_t p = 0; p < P; ++p)
    for (size_t t = 0; t < T; ++t) {
      const size_t slice = p * T + t;
      const Vec3d wi = sphericalDirection(std::sin(thetaI[t]), std::cos(thetaI[t]), phiI[p]);
      // The vndf: luminance of the value times d(omega_o) / d(u_h) = 2 pi^2 u sin(theta_h) 4 (wi . h).
      std::vector<double> density(N * N, 0.0);
      for (size_t r = 0; r < N; ++r)
        for (size_t c = 0; c < N; ++c) {
          const Vec2d u = gridPoint(r, c, N);
          const Vec3d h = halfVector(u, phiI[p], isotropic);
          if (const auto wo = reflected(wi, h)) {
            values.value(wi, *wo, value);
            const double jacobian =
                2.0 * Pi * Pi * u.x * std::sin(sqr(u.x) * PiOver2) * 4.0 * glm::dot(wi, h);
            density[r * N + c] = std::max(0.0, values.luminance(value)) * jacobian;
          }
        }
      addFloor(density);
      density = roundedToFloat32(std::move(density));
      std::copy(density.begin(), density.end(), vndf.begin() + std::ptrdiff_t(slice * N * N));
      const ParametricBilinear2D warp(density, N, N, 1, {}, Mode::Density);
      const auto blend = warp.blend({});

      // The colour over the warp's input square, and the luminance warp that follows it.
      const double sigmaWi = sigmaTable.eval(unitOfDirection(wi), unconditioned);
      std::vector<double> lum(M * M, 0.0);
      for (size_t r = 0; r < M; ++r)
        for (size_t c = 0; c < M; ++c) {
          const Vec2d uH = warp.sample(gridPoint(r, c, M), blend).point;
          std::fill(value.begin(), value.end(), 0.0);
          if (const auto wo = reflected(wi, halfVector(uH, phiI[p], isotropic))) values.value(wi, *wo, value);
          const double scale = o.jacobian ? 4.0 * sigmaWi / ndfTable.eval(uH, unconditioned) : 1.0;
          for (size_t k = 0; k < channels; ++k)
            colour[((slice * channels + k) * M + r) * M + c] = value[k] * scale;
          for (double& v : value) v *= scale;
          lum[r * M + c] = std::max(0.0, values.luminance(value));
        }
      addFloor(lum);
      std::copy(lum.begin(), lum.end(), luminance.begin() + std::ptrdiff_t(slice * M * M));
    }
  file.set(TensorField::fromValues("vndf", TensorDtype::Float32, {P, T, N, N}, vndf));
  file.set(TensorField::fromValues("luminance", TensorDtype::Float32, {P, T, M, M}, luminance));
  if (spectral) {
    file.set(TensorField::fromValues("spectra", TensorDtype::Float32, {P, T, channels, M, M}, colour));
    file.set(TensorField::fromValues("wavelengths", TensorDtype::Float32, {channels}, o.wavelengths));
  } else {
    file.set(TensorField::fromValues("rgb", TensorDtype::Float32, {P, T, 3, M, M}, colour));
  }
  file.set(TensorField::fromValues("jacobian", TensorDtype::UInt8, {1},
                                   std::vector<double>{o.jacobian ? 1.0 : 0.0}));
  file.set(TensorField::fromValues("valid", TensorDtype::UInt8, {M * M}, std::vector<double>(M * M, 255.0)));
  return file;
}

}  // namespace scatterlab
