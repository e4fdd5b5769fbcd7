// A float image: `channels` values per pixel, rows stored top to bottom (row 0 is the top of
// the picture, as in EXR's increasing-y data windows and in PNG).
#pragma once

#include <cstddef>
#include <vector>

#include "materials/core/math.h"

namespace scatterlab {

class Image {
 public:
  Image() = default;
  Image(int width, int height, int channels = 3, float fill = 0.0f)
      : width_(width), height_(height), channels_(channels), data_(size_t(width) * height * channels, fill) {}

  int width() const { return width_; }
  int height() const { return height_; }
  int channels() const { return channels_; }
  bool empty() const { return data_.empty(); }

  float* pixel(int x, int y) { return data_.data() + (size_t(y) * width_ + x) * channels_; }
  const float* pixel(int x, int y) const { return data_.data() + (size_t(y) * width_ + x) * channels_; }
  // The first three channels as a double RGB.
  Rgb rgb(int x, int y) const {
    const float* p = pixel(x, y);
    return {p[0], p[1], p[2]};
  }
  void setRgb(int x, int y, const Vec3d& value) {
    float* p = pixel(x, y);
    p[0] = float(value.x);
    p[1] = float(value.y);
    p[2] = float(value.z);
  }

  std::vector<float>& data() { return data_; }
  const std::vector<float>& data() const { return data_; }

 private:
  int width_ = 0, height_ = 0, channels_ = 3;
  std::vector<float> data_;
};

}  // namespace scatterlab
