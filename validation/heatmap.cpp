#include "validation/heatmap.h"

#include <array>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <png.h>

#include "materials/core/atomic_file.h"

namespace scatterlab {
namespace {

using Colour = std::array<double, 3>;

Colour lerp(const Colour& a, const Colour& b, double t) {
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}

// Piecewise-linear colour ramp through evenly spaced stops, t in [0, 1].
template <size_t N> Colour ramp(const std::array<Colour, N>& stops, double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * double(N - 1);
  const size_t i = std::min(size_t(t), N - 2);
  return lerp(stops[i], stops[i + 1], t - double(i));
}

// Five stops sampled from matplotlib's viridis (perceptually uniform, colour-blind safe).
constexpr std::array<Colour, 5> Viridis{{{0.267, 0.005, 0.329},
                                         {0.229, 0.322, 0.546},
                                         {0.128, 0.567, 0.551},
                                         {0.369, 0.789, 0.383},
                                         {0.993, 0.906, 0.144}}};
constexpr std::array<Colour, 3> BlueWhiteRed{
    {{0.230, 0.299, 0.754}, {0.97, 0.97, 0.97}, {0.706, 0.016, 0.150}}};

Colour colourOf(double v, HeatmapScale scale, double limit) {
  if (!std::isfinite(v)) return {1.0, 0.0, 1.0};  // magenta: a value that should not exist
  if (limit <= 0) limit = 1;
  if (scale == HeatmapScale::Sequential) return ramp(Viridis, v / limit);
  return ramp(BlueWhiteRed, 0.5 + 0.5 * v / limit);
}

void writePng(const std::filesystem::path& path, int width, int height,
              const std::vector<unsigned char>& rgb) {
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) throw std::runtime_error("cannot open " + path.string() + " for writing");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    throw std::runtime_error("libpng failed writing " + path.string());
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y)
    png_write_row(png, const_cast<png_bytep>(rgb.data() + size_t(y) * width * 3));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  if (std::fclose(file) != 0) throw std::runtime_error("cannot close " + path.string());
}

}  // namespace

void writeHeatmapPng(const std::filesystem::path& path, const Table2D& table, HeatmapScale scale,
                     double limit, int cellPixels) {
  const int width = table.cols * cellPixels, height = table.rows * cellPixels;
  std::vector<unsigned char> rgb(size_t(width) * height * 3);
  for (int y = 0; y < height; ++y) {
    const int row = table.rows - 1 - y / cellPixels;  // cos(theta) = 1 at the top
    for (int x = 0; x < width; ++x) {
      const Colour c = colourOf(table(row, x / cellPixels), scale, limit);
      for (int k = 0; k < 3; ++k)
        rgb[(size_t(y) * width + x) * 3 + k] = (unsigned char)(std::lround(c[k] * 255.0));
    }
  }
  writeFileAtomically(
      path, [&](const std::filesystem::path& temporary) { writePng(temporary, width, height, rgb); });
}

}  // namespace scatterlab
