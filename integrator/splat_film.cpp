#include "integrator/splat_film.h"

#include <algorithm>
#include <cmath>

namespace scatterlab {

SplatFilm::SplatFilm(const PinholeCamera& camera, const RenderSettings& settings)
    : settings_(settings),
      width_(camera.width()),
      height_(camera.height()),
      tilesX_((width_ + TileSize - 1) / TileSize),
      tilesY_((height_ + TileSize - 1) / TileSize),
      slices_((settings.samplesPerPixel + SliceSamples - 1) / SliceSamples),
      pixels_(size_t(width_) * size_t(height_)) {}

SplatFilm::Unit SplatFilm::chunkUnits(int index) const {
  // Slice-major: every tile's first slice of samples, then the second, so that a pixel's
  // camera values reach the film in sample order.
  const int tiles = tilesX_ * tilesY_;
  const int slice = index / tiles, tile = index % tiles;
  const int x0 = (tile % tilesX_) * TileSize, y0 = (tile / tilesX_) * TileSize;
  return {x0,
          y0,
          std::min(x0 + TileSize, width_),
          std::min(y0 + TileSize, height_),
          slice * SliceSamples,
          std::min((slice + 1) * SliceSamples, settings_.samplesPerPixel)};
}

SampleValue SplatFilm::spreadSplats(const UnitRecorder& unit, std::vector<Chunk::Splat>& scratch,
                                    Chunk& chunk) const {
  scratch.clear();
  const PixelFilter& filter = settings_.filter;
  const double reach = filter.radius();
  for (const UnitRecorder::FilmSplat& s : unit.splats_) {
    if (const SampleValue value = classifyValue(s.value); value != SampleValue::Valid) return value;
    if (!std::isfinite(s.film.x) || !std::isfinite(s.film.y)) return SampleValue::NonFinite;
    if (s.value == Rgb(0.0)) continue;
    // Pixels whose centre lies within the filter's reach of the film point.
    const int xLo = std::max(int(std::ceil(s.film.x - 0.5 - reach)), 0);
    const int xHi = std::min(int(std::floor(s.film.x - 0.5 + reach)), width_ - 1);
    const int yLo = std::max(int(std::ceil(s.film.y - 0.5 - reach)), 0);
    const int yHi = std::min(int(std::floor(s.film.y - 0.5 + reach)), height_ - 1);
    if (filter.type() == FilterType::Box) {
      // The pixel that contains the point ([i, i + 1) covers pixel i).
      const int x = int(std::floor(s.film.x)), y = int(std::floor(s.film.y));
      if (x >= 0 && y >= 0 && x < width_ && y < height_)
        scratch.push_back({uint32_t(y * width_ + x), s.value});
      continue;
    }
    for (int y = yLo; y <= yHi; ++y)
      for (int x = xLo; x <= xHi; ++x) {
        const double w = filter.density(s.film - Vec2d(x + 0.5, y + 0.5));
        if (w > 0) scratch.push_back({uint32_t(y * width_ + x), s.value * w});
      }
  }
  // One entry per pixel: the unit's total there, for the variance (header comment).
  std::sort(scratch.begin(), scratch.end(), [](const auto& a, const auto& b) { return a.pixel < b.pixel; });
  for (size_t i = 0; i < scratch.size();) {
    Chunk::Splat total = scratch[i++];
    while (i < scratch.size() && scratch[i].pixel == total.pixel) total.value += scratch[i++].value;
    chunk.splats.push_back(total);
  }
  return SampleValue::Valid;
}

void SplatFilm::add(const Chunk& chunk, int index) {
  const Unit u = chunkUnits(index);
  size_t unit = 0;
  for (int y = u.y0; y < u.y1; ++y)
    for (int x = u.x0; x < u.x1; ++x) {
      PixelSums& p = pixels_[size_t(y) * width_ + x];
      for (int s = u.sample0; s < u.sample1; ++s, ++unit) {
        // The shifted-data sums of the path tracer's film (render.cpp).
        const Rgb& value = chunk.camera[unit];
        if (p.count++ == 0) p.shift = value;
        const Rgb d = value - p.shift;
        p.sum += d;
        p.sumSquares += d * d;
        p.albedo += chunk.albedo[unit];
        p.normal += chunk.normal[unit];
      }
    }
  for (const Chunk::Splat& s : chunk.splats) {
    PixelSums& p = pixels_[s.pixel];
    p.splat += s.value;
    p.splatSquares += s.value * s.value;
  }
  statistics_.add(chunk.statistics);
}

RenderResult SplatFilm::finish(double seconds) const {
  RenderResult result;
  result.color = Image(width_, height_);
  if (settings_.albedoLayer) result.albedo = Image(width_, height_);
  if (settings_.normalLayer) result.normal = Image(width_, height_);
  if (settings_.varianceLayer) result.variance = Image(width_, height_);
  const double spp = settings_.samplesPerPixel;
  const double units = double(width_) * double(height_) * spp;
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const PixelSums& p = pixels_[size_t(y) * width_ + x];
      const double n = double(p.count);
      result.color.setRgb(x, y, p.shift + p.sum / n + p.splat / units);
      if (settings_.albedoLayer) result.albedo.setRgb(x, y, p.albedo / n);
      if (settings_.normalLayer) result.normal.setRgb(x, y, p.normal / n);
      if (settings_.varianceLayer) {
        const Rgb camera =
            n < 2 ? Rgb(0.0) : glm::max(p.sumSquares - p.sum * p.sum / n, Rgb(0.0)) / (n * (n - 1.0));
        const Rgb splats = units < 2 ? Rgb(0.0)
                                     : glm::max(p.splatSquares - p.splat * p.splat / units, Rgb(0.0)) /
                                           (units * (units - 1.0));
        result.variance.setRgb(x, y, camera + splats);
      }
    }
  result.statistics.seconds = seconds;
  result.statistics.samples = uint64_t(units);
  result.statistics.vertices = statistics_.vertices;
  result.statistics.nonFiniteSamples = statistics_.nonFiniteSamples;
  result.statistics.negativeSamples = statistics_.negativeSamples;
  return result;
}

}  // namespace scatterlab
