#include <gtest/gtest.h>

#include <fstream>

#include "validation/heatmap.h"

namespace scatterlab {
namespace heatmap_test {

TEST(Heatmap, WritesPngOfExpectedSize) {
  const std::filesystem::path dir = std::filesystem::path(SCATTERLAB_TEST_OUTPUT_DIR) / "heatmap";
  std::filesystem::create_directories(dir);
  Table2D t(4, 8);
  for (size_t i = 0; i < t.values.size(); ++i) t.values[i] = double(i);
  t(0, 0) = NAN;  // drawn magenta, not a crash
  const auto path = dir / "ramp.png";
  writeHeatmapPng(path, t, HeatmapScale::Sequential, 31.0, 3);
  std::ifstream in(path, std::ios::binary);
  unsigned char header[24];
  ASSERT_TRUE(in.read(reinterpret_cast<char*>(header), 24));
  // PNG signature, then the IHDR chunk: width and height big-endian at bytes 16 and 20.
  EXPECT_EQ(header[1], 'P');
  EXPECT_EQ(header[2], 'N');
  EXPECT_EQ(header[3], 'G');
  const auto be32 = [&](int o) {
    return (header[o] << 24) | (header[o + 1] << 16) | (header[o + 2] << 8) | header[o + 3];
  };
  EXPECT_EQ(be32(16), 8 * 3);
  EXPECT_EQ(be32(20), 4 * 3);
  // No temporary file is left behind.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
}

TEST(Heatmap, UnwritableDirectoryThrowsInsteadOfCrashing) {
  EXPECT_THROW(writeHeatmapPng("/nonexistent-dir/x.png", Table2D(2, 2), HeatmapScale::Diverging, 1.0),
               std::runtime_error);
}

}  // namespace heatmap_test
}  // namespace scatterlab
