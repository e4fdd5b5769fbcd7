#include "integrator/png_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include <png.h>

#include "integrator/render_error.h"
#include "materials/core/atomic_file.h"

namespace scatterlab {

double srgbEncode(double linear) {
  if (!(linear > 0.0031308)) return 12.92 * std::max(linear, 0.0);
  return 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

std::vector<uint8_t> toSrgb8(const Image& image, double exposure) {
  const double scale = std::exp2(exposure);
  std::vector<uint8_t> out(size_t(image.width()) * image.height() * 3);
  size_t k = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const float* p = image.pixel(x, y);
      for (int c = 0; c < 3; ++c) {
        const double v = double(p[c]) * scale;
        const double encoded = std::isfinite(v) ? srgbEncode(std::clamp(v, 0.0, 1.0)) : 0.0;
        out[k++] = uint8_t(std::lround(255.0 * encoded));
      }
    }
  return out;
}

namespace {

// libpng reports errors by longjmp: everything that owns resources lives outside the setjmp
// frame, and the frame itself holds only plain data.
void writePngFile(const std::filesystem::path& path, int width, int height, const std::vector<uint8_t>& rgb) {
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!file) throw std::runtime_error("cannot open for writing");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  std::vector<png_bytep> rows(static_cast<size_t>(height));
  for (int y = 0; y < height; ++y) rows[y] = const_cast<png_bytep>(rgb.data() + size_t(y) * width * 3);
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("libpng failed");
  }
  png_init_io(png, file.get());
  png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_set_rows(png, info, rows.data());
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  png_destroy_write_struct(&png, &info);
  if (std::fflush(file.get()) != 0) throw std::runtime_error("cannot flush");
}

}  // namespace

void writePngRgb8(const std::filesystem::path& path, int width, int height, const std::vector<uint8_t>& rgb) {
  if (width < 1 || height < 1 || rgb.size() != size_t(width) * height * 3)
    throw std::invalid_argument("writePngRgb8: size does not match the data");
  try {
    writeFileAtomically(
        path, [&](const std::filesystem::path& temporary) { writePngFile(temporary, width, height, rgb); });
  } catch (const std::exception& error) {
    throw RenderInputError("cannot write \"" + path.string() + "\": " + error.what() +
                           "; allowed: a writable path in an existing directory");
  }
}

void writePngSrgb(const std::filesystem::path& path, const Image& image, double exposure) {
  writePngRgb8(path, image.width(), image.height(), toSrgb8(image, exposure));
}

}  // namespace scatterlab
