// Fuzz harness (fuzz/harness/harness.h): an OpenEXR environment map
// (integrator/environment_map_file.h), the bytes as a file, read and turned into the
// renderer's environment with its sampling tables, then sampled and looked up.
#include <unistd.h>

#include <cmath>
#include <cstdlib>

#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz/harness/harness.h"
#include "integrator/environment.h"
#include "integrator/environment_map_file.h"
#include "integrator/render_error.h"

namespace scatterlab::fuzz {

namespace {

// OpenEXR reads files by name: one scratch file per process, in memory where possible.
std::filesystem::path scratchFile() {
  const std::filesystem::path shm("/dev/shm");
  std::error_code error;
  const std::filesystem::path directory =
      std::filesystem::is_directory(shm, error) ? shm : std::filesystem::temp_directory_path();
  return directory / ("scatterlab-fuzz-" + std::to_string(::getpid()) + ".exr");
}

}  // namespace

void exrEnvironmentMap(Input data) {
  static const std::filesystem::path file = scratchFile();
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size()));
  }
  try {
    // The reader allows 2^25 pixels: a header claiming that many costs a 0.4 GB image and its
    // sampling tables for a few bytes of input. Below 2^16 pixels (a 256 x 128 map is half that)
    // every code path is the same, the refusal of a larger window included; the full limit's
    // refusal has its own tests (tests/integrator/image_io_test.cpp, EnvironmentMapFile).
    constexpr long FuzzMaxPixels = 1L << 16;
    EnvironmentMapFile map = readEnvironmentMap(file, FuzzMaxPixels);
    const Environment environment = Environment::fromMap(std::move(map.image));
    // The renderer's use of it: a map the reader accepts gives finite radiance and a valid
    // density wherever it is sampled or looked up.
    for (const Vec2d u : {Vec2d(0.1, 0.2), Vec2d(0.5, 0.5), Vec2d(0.999, 0.001)}) {
      if (const auto sample = environment.sample(u)) {
        if (!(sample->pdf > 0.0) || !std::isfinite(sample->pdf) || !isFinite(sample->radiance)) std::abort();
      }
      if (!isFinite(environment.eval(Vec3d(u.x - 0.5, u.y - 0.5, 0.5)))) std::abort();
    }
  } catch (const RenderInputError&) {}
}

}  // namespace scatterlab::fuzz
