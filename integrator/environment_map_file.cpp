#include "integrator/environment_map_file.h"

#include <cmath>
#include <sstream>

#include "integrator/exr_io.h"
#include "integrator/render_error.h"

namespace scatterlab {

namespace {

[[noreturn]] void badValue(const std::string& name, const Image& image, size_t index,
                           const std::string& allowed) {
  const size_t pixel = index / 3;
  std::ostringstream message;
  message << name << ": pixel (" << pixel % size_t(image.width()) << ", " << pixel / size_t(image.width())
          << ") channel "
          << "RGB"[index % 3] << " is " << image.data()[index] << "; allowed: " << allowed;
  throw RenderInputError(message.str());
}

}  // namespace

EnvironmentMapFile readEnvironmentMap(const std::filesystem::path& path, long maxPixels) {
  const std::string name = "environment map \"" + path.string() + "\"";
  EnvironmentMapFile file{readExrRgb(path, "environment map", maxPixels)};
  Image& image = file.image;
  if (image.width() != 2 * image.height())
    throw RenderInputError(
        name + ": " + std::to_string(image.width()) + " x " + std::to_string(image.height()) +
        " pixels is not an equirectangular map; allowed: width = 2 x height, e.g. 1024 x 512");
  std::vector<float>& values = image.data();
  double sum = 0.0;
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) badValue(name, image, i, "finite radiance");
    sum += values[i];
  }
  const double floor = -NegativeTolerance * std::max(sum / double(values.size()), 0.0);
  for (size_t i = 0; i < values.size(); ++i) {
    if (values[i] >= 0) continue;
    if (values[i] < floor) {
      std::ostringstream allowed;
      allowed << "radiance >= 0 (values down to " << floor << ", " << NegativeTolerance * 100
              << "% of the map's mean, are taken as 0)";
      badValue(name, image, i, allowed.str());
    }
    file.mostNegative = std::min(file.mostNegative, double(values[i]));
    values[i] = 0.0f;
    ++file.clampedNegatives;
  }
  return file;
}

}  // namespace scatterlab
