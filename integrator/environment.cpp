#include "integrator/environment.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "materials/core/warp.h"

namespace scatterlab {

Environment Environment::constant(const Rgb& radiance) {
  if (!isFinite(radiance) || radiance.x < 0 || radiance.y < 0 || radiance.z < 0)
    throw std::invalid_argument("Environment: radiance must be finite and non-negative");
  Environment e;
  e.constant_ = radiance;
  return e;
}

Environment Environment::fromMap(Image image, double strength, const Transform& mapToWorld) {
  const int width = image.width(), height = image.height();
  if (image.channels() != 3 || height < 1 || width != 2 * height)
    throw std::invalid_argument("Environment: map must be a 3-channel image twice as wide as tall");
  if (!(strength >= 0) || !std::isfinite(strength))
    throw std::invalid_argument("Environment: strength must be >= 0");
  for (float v : image.data())
    if (!(v >= 0) || !std::isfinite(v))
      throw std::invalid_argument("Environment: radiance must be finite and >= 0");

  auto map = std::make_shared<Map>();
  map->width = width;
  map->height = height;
  map->mapToWorld = mapToWorld.linear();
  map->worldToMap = glm::transpose(map->mapToWorld);  // a rotation: inverse = transpose
  map->rowCos.resize(size_t(height) + 1);
  for (int r = 0; r <= height; ++r) map->rowCos[r] = std::cos(Pi * double(r) / height);
  map->rowCos.front() = 1.0;
  map->rowCos.back() = -1.0;

  // Cell weights (header comment): luminance of the bilinear radiance integrated over the
  // cell, (1/8, 3/4, 1/8) per axis over the 3 x 3 neighbourhood (wrapping in u, clamped in
  // t), times the cell's solid angle.
  std::vector<double> lum(size_t(width) * height);
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c) lum[size_t(r) * width + c] = luminance(image.rgb(c, r));
  constexpr double Stencil[3] = {0.125, 0.75, 0.125};
  std::vector<double> weights(size_t(width) * height);
  for (int r = 0; r < height; ++r) {
    const double solidAngle = (2.0 * Pi / width) * (map->rowCos[r] - map->rowCos[r + 1]);
    for (int c = 0; c < width; ++c) {
      double sum = 0;
      for (int dr = -1; dr <= 1; ++dr) {
        const int rr = std::clamp(r + dr, 0, height - 1);
        for (int dc = -1; dc <= 1; ++dc) {
          const int cc = (c + dc + width) % width;
          sum += Stencil[dr + 1] * Stencil[dc + 1] * lum[size_t(rr) * width + cc];
        }
      }
      weights[size_t(r) * width + c] = sum * solidAngle;
    }
  }
  map->distribution = PiecewiseConstant2D(weights, size_t(height), size_t(width));
  map->black = !(map->distribution.total() > 0) || strength == 0;
  map->luminanceIntegral = map->distribution.total() * strength;
  map->texels.resize(size_t(width) * height * 4);
  for (int r = 0; r < height; ++r) {
    const double solidAngle = (2.0 * Pi / width) * (map->rowCos[r] - map->rowCos[r + 1]);
    for (int c = 0; c < width; ++c) {
      float* t = map->texels.data() + (size_t(r) * width + c) * 4;
      const Rgb radiance = image.rgb(c, r) * strength;
      t[0] = float(radiance.x);
      t[1] = float(radiance.y);
      t[2] = float(radiance.z);
      t[3] = map->black ? 0.0f : float(map->distribution.probability(size_t(r), size_t(c)) / solidAngle);
    }
  }
  Environment e;
  e.map_ = std::move(map);
  return e;
}

Vec2d Environment::equirectFromDirection(const Vec3d& w) {
  const double t = safeAcos(w.z) * InvPi;
  double u = (Pi - std::atan2(w.y, w.x)) * Inv2Pi;  // phi in (-pi, pi] -> u in [0, 1)
  if (u >= 1.0) u -= 1.0;
  return {u, t};
}

Vec3d Environment::directionFromEquirect(const Vec2d& ut) {
  const double theta = Pi * ut.y, phi = Pi - 2.0 * Pi * ut.x;
  const double sinTheta = std::sin(theta);
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), std::cos(theta)};
}

EnvironmentValue Environment::lookup(const Vec2d& ut) const {
  const Map& m = *map_;
  const int width = m.width, height = m.height;
  const double x = ut.x * width - 0.5, y = std::clamp(ut.y * height - 0.5, 0.0, double(height - 1));
  const double fx = std::floor(x), fy = std::floor(y);
  const double tx = x - fx, ty = y - fy;
  int x0 = int(fx);
  if (x0 < 0) x0 += width;
  const int x1 = x0 + 1 == width ? 0 : x0 + 1;
  const int y0 = int(fy), y1 = std::min(y0 + 1, height - 1);
  const float* p00 = m.texel(x0, y0);
  const float* p10 = m.texel(x1, y0);
  const float* p01 = m.texel(x0, y1);
  const float* p11 = m.texel(x1, y1);
  EnvironmentValue out;
  for (int c = 0; c < 3; ++c)
    out.radiance[c] = (1 - ty) * ((1 - tx) * p00[c] + tx * p10[c]) + ty * ((1 - tx) * p01[c] + tx * p11[c]);
  // The cell of (u, t) is column floor(u W), row floor(t H): one of the four texels read.
  const bool right = ut.x * width >= double(x0) + 1.0 || (x0 == width - 1 && ut.x * width < 0.5);
  const bool lower = ut.y * height >= double(y0) + 1.0;
  const float* cell = right ? (lower ? p11 : p10) : (lower ? p01 : p00);
  out.pdf = cell[3];
  return out;
}

Rgb Environment::eval(const Vec3d& direction) const {
  if (!map_) return constant_;
  return lookup(equirectFromDirection(map_->worldToMap * direction)).radiance;
}

EnvironmentValue Environment::evalWithPdf(const Vec3d& direction) const {
  if (!map_) return {constant_, constant_ == Rgb(0.0) ? 0.0 : uniformSpherePdf()};
  return lookup(equirectFromDirection(map_->worldToMap * direction));
}

std::optional<EnvironmentSample> Environment::sample(const Vec2d& u) const {
  if (!map_) {
    if (constant_ == Rgb(0.0)) return std::nullopt;
    return EnvironmentSample{sampleUniformSphere(u), constant_, uniformSpherePdf()};
  }
  const Map& m = *map_;
  if (m.black) return std::nullopt;
  const auto cell = m.distribution.sample(u);
  const double cosHi = m.rowCos[cell.row], cosLo = m.rowCos[cell.row + 1];
  const double cosTheta = cosHi + cell.remapped.x * (cosLo - cosHi);
  const double sinTheta = safeSqrt(1.0 - cosTheta * cosTheta);
  const double uCoordinate = (double(cell.column) + cell.remapped.y) / m.width;
  const double phi = Pi - 2.0 * Pi * uCoordinate;
  const Vec3d local(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
  // The cell's own density (the lookup at a point on a cell edge could read its neighbour's).
  const double pdf = m.texel(int(cell.column), int(cell.row))[3];
  const double t = std::clamp(safeAcos(cosTheta) * InvPi, 0.0, 1.0);
  return EnvironmentSample{m.mapToWorld * local, lookup({uCoordinate, t}).radiance, pdf};
}

double Environment::pdf(const Vec3d& direction) const { return evalWithPdf(direction).pdf; }

double Environment::luminanceIntegral() const {
  return map_ ? map_->luminanceIntegral : 4.0 * Pi * luminance(constant_);
}

}  // namespace scatterlab
