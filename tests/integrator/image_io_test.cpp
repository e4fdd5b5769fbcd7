// EXR and PNG files: round trips with layers, the sRGB encoding and exposure, and every kind
// of bad environment map (missing, a directory, not EXR, truncated, no colour channels, not
// 2:1, NaN or infinity, negative) rejected with a message naming the file and the problem.
// Writes are atomic: a write that fails leaves nothing behind.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <OpenEXR/ImfBoxAttribute.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfChromaticitiesAttribute.h>
#include <OpenEXR/ImfDeepImageStateAttribute.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfEnvmapAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfKeyCodeAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfRationalAttribute.h>
#include <OpenEXR/ImfTileDescriptionAttribute.h>
#include <OpenEXR/ImfTimeCodeAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>

#include "integrator/environment_map_file.h"
#include "integrator/exr_io.h"
#include "integrator/png_io.h"
#include "integrator/render_error.h"
#include "render_test_support.h"

namespace scatterlab {
namespace image_io_test {

namespace fs = std::filesystem;
using render_test::scratchPath;

Image gradient(int width, int height, float scale = 1.0f) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.setRgb(x, y, Rgb(x * 0.5, y * 0.25, 1e4 * (x + y)) * double(scale));
  return image;
}

// The message of the RenderInputError that `f` throws, or a failure.
template <typename F> std::string errorOf(const F& f) {
  try {
    f();
  } catch (const RenderInputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no RenderInputError";
  return "";
}

void expectMentions(const std::string& text, const std::vector<std::string>& fragments) {
  for (const std::string& fragment : fragments)
    EXPECT_NE(text.find(fragment), std::string::npos) << "\"" << fragment << "\" missing from: " << text;
}

TEST(Exr, RoundTripsFloatRgbAndLayers) {
  const fs::path path = scratchPath("layers") += ".exr";
  const Image color = gradient(7, 5), albedo = gradient(7, 5, 0.5f), normal = gradient(7, 5, -1.0f);
  writeExr(path, {{"", {"R", "G", "B"}, &color},
                  {"albedo", {"R", "G", "B"}, &albedo},
                  {"normal", {"X", "Y", "Z"}, &normal}});
  const Image back = readExrRgb(path);
  EXPECT_EQ(back.width(), 7);
  EXPECT_EQ(back.height(), 5);
  EXPECT_EQ(back.data(), color.data());  // 32-bit float: bit-exact
  fs::remove(path);
}

TEST(Exr, FailedWriteLeavesNothing) {
  const fs::path path = scratchPath("missing-dir") / "out.exr";
  const Image color = gradient(4, 2);
  const std::string message = errorOf([&] { writeExr(path, {{"", {"R", "G", "B"}, &color}}); });
  expectMentions(message, {path.string()});
  EXPECT_FALSE(fs::exists(path.parent_path()));
  // The image is written in full to a temporary file, then renaming it over an occupied name
  // (a non-empty directory) fails: the temporary is removed, nothing else is touched.
  const fs::path folder = scratchPath("occupied");
  fs::create_directories(folder / "out.exr" / "inside");
  expectMentions(errorOf([&] {
                   writeExr(folder / "out.exr", {{"", {"R", "G", "B"}, &color}});
                 }),
                 {"out.exr"});
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 1);
  EXPECT_TRUE(fs::is_directory(folder / "out.exr" / "inside"));
}

TEST(Png, EncodesSrgbWithExposure) {
  EXPECT_DOUBLE_EQ(srgbEncode(0.0), 0.0);
  EXPECT_DOUBLE_EQ(srgbEncode(1.0), 1.0);
  EXPECT_NEAR(srgbEncode(0.18), 0.4614, 1e-4);           // middle grey
  EXPECT_NEAR(srgbEncode(0.002), 12.92 * 0.002, 1e-15);  // the linear toe
  Image image(3, 1);
  image.setRgb(0, 0, Rgb(0.25, 0.5, 2.0));
  image.setRgb(1, 0, Rgb(-1.0, 0.0, 1e9));
  image.setRgb(2, 0, Rgb(0.1));
  const std::vector<uint8_t> plain = toSrgb8(image), brighter = toSrgb8(image, 1.0);
  EXPECT_EQ(plain[0], uint8_t(std::lround(255 * srgbEncode(0.25))));
  EXPECT_EQ(brighter[0], uint8_t(std::lround(255 * srgbEncode(0.5))));  // +1 stop = x2
  EXPECT_EQ(plain[2], 255);                                             // clamped
  EXPECT_EQ(plain[3], 0);
  EXPECT_EQ(plain[5], 255);
}

TEST(Png, WritesAValidHeader) {
  const fs::path path = scratchPath("image") += ".png";
  writePngSrgb(path, gradient(9, 4, 1e-5f));
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), {});
  ASSERT_GT(bytes.size(), 24u);
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  EXPECT_TRUE(std::equal(signature, signature + 8, bytes.begin()));
  const auto be32 = [&](size_t at) {
    return (bytes[at] << 24) | (bytes[at + 1] << 16) | (bytes[at + 2] << 8) | bytes[at + 3];
  };
  EXPECT_EQ(be32(16), 9);  // IHDR width
  EXPECT_EQ(be32(20), 4);  // IHDR height
  fs::remove(path);
}

// ---- Bad environment maps -------------------------------------------------------------------

fs::path writeMap(const std::string& stem, const Image& image) {
  const fs::path path = scratchPath(stem) += ".exr";
  writeExr(path, {{"", {"R", "G", "B"}, &image}});
  return path;
}

TEST(EnvironmentMapFile, ReadsAGoodMap) {
  const fs::path path = writeMap("good", render_test::smoothSkyMap(8));
  const EnvironmentMapFile file = readEnvironmentMap(path);
  EXPECT_EQ(file.image.width(), 16);
  EXPECT_EQ(file.clampedNegatives, 0u);
}

TEST(EnvironmentMapFile, ReadsTheShippedMaps) {
  for (const char* name : {"city", "courtyard", "forest", "studio"}) {
    const EnvironmentMapFile file =
        readEnvironmentMap(fs::path(SCATTERLAB_DATA_DIR) / "envmaps" / (std::string(name) + ".exr"));
    EXPECT_EQ(file.image.width(), 1024) << name;
    EXPECT_EQ(file.image.height(), 512) << name;
    EXPECT_NO_THROW(Environment::fromMap(file.image)) << name;
  }
}

TEST(EnvironmentMapFile, RejectsMissingFilesAndDirectories) {
  const fs::path missing = scratchPath("absent") += ".exr";
  expectMentions(errorOf([&] { readEnvironmentMap(missing); }), {missing.string(), "no such file"});
  const fs::path directory = scratchPath("a-directory");
  fs::create_directories(directory);
  expectMentions(errorOf([&] { readEnvironmentMap(directory); }), {directory.string(), "is a directory"});
}

TEST(EnvironmentMapFile, RejectsFilesThatAreNotExr) {
  const fs::path text = scratchPath("text") += ".exr";
  std::ofstream(text) << "this is not an image\n";
  expectMentions(errorOf([&] { readEnvironmentMap(text); }), {text.string(), "cannot be read as OpenEXR"});
  // A real map cut in half.
  const fs::path whole = writeMap("whole", render_test::smoothSkyMap(32));
  const fs::path truncated = scratchPath("truncated") += ".exr";
  fs::copy_file(whole, truncated);
  fs::resize_file(truncated, fs::file_size(whole) / 2);
  expectMentions(errorOf([&] { readEnvironmentMap(truncated); }),
                 {truncated.string(), "cannot be read as OpenEXR"});
}

TEST(EnvironmentMapFile, RejectsFilesWithoutColour) {
  const fs::path path = scratchPath("normals") += ".exr";
  const Image image = gradient(8, 4);
  writeExr(path, {{"normal", {"X", "Y", "Z"}, &image}});
  expectMentions(errorOf([&] { readEnvironmentMap(path); }), {path.string(), "normal.X", "R, G and B"});
}

// A header claiming 16384 x 8192 pixels (2^27) in a file of a few KB: refused from the header,
// before anything is allocated for the pixels.
TEST(EnvironmentMapFile, RejectsADataWindowOverTheLimitFromTheHeaderAlone) {
  const fs::path path = scratchPath("huge-header") += ".exr";
  {
    Imf::Header header(16384, 8192);
    for (const char* channel : {"R", "G", "B"}) header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
    Imf::OutputFile file(path.c_str(), header);  // no pixels written: the header and an empty offset table
  }
  expectMentions(
      errorOf([&] { readEnvironmentMap(path); }),
      {path.string(), "16384 x 8192", "at most 33554432 pixels (8192 x 4096)", "before the pixels"});
}

// A header attribute declaring 1 GB in a file of a few dozen bytes: refused before OpenEXR would
// allocate the declared size to read it.
TEST(EnvironmentMapFile, RejectsAHeaderAttributeLargerThanTheFile) {
  const fs::path path = scratchPath("huge-attribute") += ".exr";
  {
    std::ofstream out(path, std::ios::binary);
    const unsigned char start[8] = {0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0};  // magic, version 2
    out.write(reinterpret_cast<const char*>(start), 8);
    out.write("comments\0string\0", 16);
    const unsigned char size[4] = {0, 0, 0, 0x40};  // 2^30, little-endian
    out.write(reinterpret_cast<const char*>(size), 4);
    out << "a few bytes";
  }
  expectMentions(errorOf([&] { readEnvironmentMap(path); }),
                 {path.string(), "\"comments\" (string) declares 1073741824 bytes, but 11 are left"});
}

// A good map whose header attribute `attributeAndType` ("name\0type\0") has its size field set to
// `size`, as a file whose size fields lie.
fs::path mapWithAttributeSize(const std::string& stem, const std::string& attributeAndType, uint32_t size) {
  const fs::path path = writeMap(stem, render_test::smoothSkyMap(8));
  std::fstream file(path, std::ios::binary | std::ios::in | std::ios::out);
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const size_t at = bytes.find(attributeAndType);
  if (at == std::string::npos) {
    ADD_FAILURE() << "the writer's header has no " << attributeAndType;
    return path;
  }
  const unsigned char little[4] = {uint8_t(size), uint8_t(size >> 8), uint8_t(size >> 16),
                                   uint8_t(size >> 24)};
  file.seekp(std::streamoff(at + attributeAndType.size()));
  file.write(reinterpret_cast<const char*>(little), 4);
  return path;
}

// OpenEXR reads a fixed-size value by its layout, whatever size is declared, and would then read
// the next attribute from the wrong place; the walk refuses the size (a float is 4 bytes).
TEST(EnvironmentMapFile, RejectsAFixedSizeAttributeOfAnotherSize) {
  const std::string attribute("pixelAspectRatio\0float\0", 23);
  const fs::path path = mapWithAttributeSize("float-of-8-bytes", attribute, 8);
  expectMentions(
      errorOf([&] { readEnvironmentMap(path); }),
      {path.string(), "\"pixelAspectRatio\" (float) declares 8 bytes; allowed: 4, the size of a float"});
}

// The walk's fixed sizes are the sizes OpenEXR itself writes: a map whose header holds an
// attribute of every fixed-size type, written by OpenEXR, passes the walk and reads (box2i,
// compression, float, lineOrder and the channel list are in every header).
TEST(EnvironmentMapFile, ReadsAMapWithAnAttributeOfEveryFixedSizeType) {
  const fs::path path = scratchPath("every-attribute-type") += ".exr";
  {
    Imf::Header header(16, 8);
    for (const char* channel : {"R", "G", "B"}) header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
    header.insert("aBox2f", Imf::Box2fAttribute(Imath::Box2f(Imath::V2f(0, 0), Imath::V2f(1, 1))));
    header.insert("aChromaticities", Imf::ChromaticitiesAttribute(Imf::Chromaticities()));
    header.insert("aDeepImageState", Imf::DeepImageStateAttribute(Imf::DIS_MESSY));
    header.insert("aDouble", Imf::DoubleAttribute(0.5));
    header.insert("aEnvmap", Imf::EnvmapAttribute(Imf::ENVMAP_LATLONG));
    header.insert("aInt", Imf::IntAttribute(3));
    header.insert("aKeycode", Imf::KeyCodeAttribute(Imf::KeyCode()));
    header.insert("aM33f", Imf::M33fAttribute(Imath::M33f()));
    header.insert("aM33d", Imf::M33dAttribute(Imath::M33d()));
    header.insert("aM44f", Imf::M44fAttribute(Imath::M44f()));
    header.insert("aM44d", Imf::M44dAttribute(Imath::M44d()));
    header.insert("aRational", Imf::RationalAttribute(Imf::Rational(1, 2)));
    header.insert("aTiledesc", Imf::TileDescriptionAttribute(Imf::TileDescription()));
    header.insert("aTimecode", Imf::TimeCodeAttribute(Imf::TimeCode()));
    header.insert("aV2i", Imf::V2iAttribute(Imath::V2i(1, 2)));
    header.insert("aV2f", Imf::V2fAttribute(Imath::V2f(1, 2)));
    header.insert("aV2d", Imf::V2dAttribute(Imath::V2d(1, 2)));
    header.insert("aV3i", Imf::V3iAttribute(Imath::V3i(1, 2, 3)));
    header.insert("aV3f", Imf::V3fAttribute(Imath::V3f(1, 2, 3)));
    header.insert("aV3d", Imf::V3dAttribute(Imath::V3d(1, 2, 3)));
    std::vector<float> pixels(16 * 8, 0.5f);
    Imf::FrameBuffer frame;
    for (const char* channel : {"R", "G", "B"})
      frame.insert(channel, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data()), sizeof(float),
                                       16 * sizeof(float)));
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(8);
  }
  EXPECT_EQ(readEnvironmentMap(path).image.width(), 16);  // a size the walk refused would throw
}

// A channel list is read up to its end marker: R, G and B take 3 x (2 + 16) + 1 = 55 bytes, so a
// size of 71 is refused.
TEST(EnvironmentMapFile, RejectsAChannelListOfAnotherSizeThanDeclared) {
  const std::string attribute("channels\0chlist\0", 16);
  const fs::path path = mapWithAttributeSize("chlist-of-71-bytes", attribute, 71);
  expectMentions(errorOf([&] { readEnvironmentMap(path); }),
                 {path.string(), "\"channels\" (chlist) declares 71 bytes, but its channel list takes 55"});
}

// A caller's lower limit (the fuzz harness's): a 16 x 8 map passes at 128 pixels and is refused at 127.
TEST(EnvironmentMapFile, ALowerPixelLimitRefusesALargerMap) {
  const fs::path path = writeMap("limit", render_test::smoothSkyMap(8));
  EXPECT_EQ(readEnvironmentMap(path, 128).image.width(), 16);
  expectMentions(errorOf([&] { readEnvironmentMap(path, 127); }),
                 {path.string(), "16 x 8", "at most 127 pixels,"});
}

TEST(EnvironmentMapFile, RejectsMapsThatAreNotEquirectangular) {
  const fs::path path = writeMap("square", Image(16, 16, 3, 1.0f));
  expectMentions(errorOf([&] { readEnvironmentMap(path); }),
                 {path.string(), "16 x 16", "width = 2 x height"});
}

TEST(EnvironmentMapFile, RejectsNonFiniteValues) {
  for (const float bad : {NAN, INFINITY}) {
    Image image = render_test::smoothSkyMap(8);
    image.pixel(5, 3)[2] = bad;
    const fs::path path = writeMap("nonfinite", image);
    expectMentions(errorOf([&] { readEnvironmentMap(path); }),
                   {path.string(), "pixel (5, 3) channel B", "finite"});
  }
}

TEST(EnvironmentMapFile, RejectsNegativeValuesAndClampsRoundOff) {
  Image image = render_test::smoothSkyMap(8);
  image.pixel(4, 2)[1] = -0.5f;
  const fs::path bad = writeMap("negative", image);
  expectMentions(errorOf([&] { readEnvironmentMap(bad); }),
                 {bad.string(), "pixel (4, 2) channel G is -0.5", ">= 0"});
  // Out-of-gamut round-off, far below 1% of the mean: set to 0 and counted.
  image.pixel(4, 2)[1] = -1e-4f;
  const EnvironmentMapFile file = readEnvironmentMap(writeMap("roundoff", image));
  EXPECT_EQ(file.clampedNegatives, 1u);
  EXPECT_FLOAT_EQ(float(file.mostNegative), -1e-4f);
  EXPECT_EQ(file.image.pixel(4, 2)[1], 0.0f);
}

}  // namespace image_io_test
}  // namespace scatterlab
