// The MERL format (docs/references.md, "MERL BRDF binary format"): layout, binning, the half/diff
// change of variables, bit-exact round trips, and the reader's and writer's errors.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>

#include "materials/core/rng.h"
#include "materials/core/warp.h"
#include "materials/measured/half_diff.h"
#include "materials/measured/merl_io.h"
#include "measured_test_support.h"

namespace scatterlab {
namespace merl_io_test {

namespace fs = std::filesystem;
using measured_test::scratchPath;

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void writeBytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

// The bytes of a MERL file written by hand, independently of writeMerl: little-endian
// header, then the channel-planar doubles (this machine is little-endian; checked below).
std::string handWrittenFile(const std::vector<double>& stored,
                            std::array<int32_t, 3> header = {90, 90, 180}) {
  std::string bytes(12 + stored.size() * 8, '\0');
  std::memcpy(bytes.data(), header.data(), 12);
  std::memcpy(bytes.data() + 12, stored.data(), stored.size() * 8);
  return bytes;
}

// A table with varied values, some missing cells and one channel negative alone.
MerlTable variedTable() {
  MerlTable table;
  CounterRng rng(7, 0);
  for (size_t cell = 0; cell < merl::CellCount; cell += 1)
    for (int c = 0; c < 3; ++c) table.setStored(c, cell, rng.uniform() * 1000.0);
  table.setMissing(12345);
  table.setMissing(merl::CellCount - 1);
  table.setStored(1, 777, -0.5);
  return table;
}

std::string readErrorOf(const fs::path& path) {
  try {
    readMerl(path);
  } catch (const MerlError& error) {
    return error.what();
  }
  return "";
}

void expectMentions(const std::string& message, const std::vector<std::string>& fragments) {
  for (const std::string& fragment : fragments)
    EXPECT_NE(message.find(fragment), std::string::npos)
        << "\"" << fragment << "\" missing from: " << message;
}

// ---- Layout -------------------------------------------------------------------------------

TEST(MerlFormat, SizesAndIndexMatchTheReference) {
  EXPECT_EQ(merl::CellCount, 1'458'000u);
  EXPECT_EQ(merl::FileBytes, 34'992'012u);
  // index = phi_d + 180 theta_d + 180 * 90 theta_h (phi_d fastest)
  EXPECT_EQ(merl::cellIndex(0, 0, 1), 1u);
  EXPECT_EQ(merl::cellIndex(0, 1, 0), 180u);
  EXPECT_EQ(merl::cellIndex(1, 0, 0), 16200u);
  EXPECT_EQ(merl::cellIndex(89, 89, 179), merl::CellCount - 1);
  const merl::CellCoordinates c = merl::cellCoordinates(merl::cellIndex(17, 42, 123));
  EXPECT_EQ(c.thetaHalf, 17);
  EXPECT_EQ(c.thetaDiff, 42);
  EXPECT_EQ(c.phiDiff, 123);
}

TEST(MerlFormat, ThetaHalfCellsAreNonLinear) {
  // Cell i starts at theta_h = (i / 90)^2 * 90 degrees.
  for (int i : {0, 1, 2, 5, 30, 89}) {
    const double start = radians(sqr(i / 90.0) * 90.0);
    const double end = radians(sqr((i + 1) / 90.0) * 90.0);
    EXPECT_EQ(merl::thetaHalfCell(start + 1e-3 * (end - start)), i) << i;
    EXPECT_EQ(merl::thetaHalfCell(end - 1e-3 * (end - start)), i) << i;
  }
  EXPECT_EQ(merl::thetaHalfCell(radians(1.0)), int(std::sqrt(1.0 / 90.0) * 90.0));  // 9: dense near the pole
  EXPECT_EQ(merl::thetaHalfCell(PiOver2), 89);  // clamped to the last cell
}

TEST(MerlFormat, ThetaDiffAndPhiDiffCells) {
  EXPECT_EQ(merl::thetaDiffCell(radians(0.5)), 0);
  EXPECT_EQ(merl::thetaDiffCell(radians(45.5)), 45);
  EXPECT_EQ(merl::thetaDiffCell(PiOver2), 89);
  EXPECT_EQ(merl::phiDiffCell(radians(10.5)), 10);
  EXPECT_EQ(merl::phiDiffCell(radians(-10.5)), 169);  // +pi by reciprocity: 169.5 degrees
  EXPECT_EQ(merl::phiDiffCell(Pi), 179);              // atan2 can return exactly pi
  EXPECT_EQ(merl::phiDiffCell(std::atan2(0.0, -1.0)), 179);
}

TEST(MerlFormat, ChannelScalesAreAppliedOnReadAndDividedOnWrite) {
  MerlTable table;
  table.setValue(0, 5, 1.0);
  table.setValue(1, 5, 1.0);
  table.setValue(2, 5, 1.0);
  EXPECT_DOUBLE_EQ(table.stored(0, 5), 1500.0);
  EXPECT_DOUBLE_EQ(table.stored(1, 5), 1500.0 / 1.15);
  EXPECT_DOUBLE_EQ(table.stored(2, 5), 1500.0 / 1.66);
  table.setStored(2, 6, 1500.0);
  EXPECT_DOUBLE_EQ(table.value(2, 6), 1.66);
}

// ---- Half/diff angles ----------------------------------------------------------------------

TEST(HalfDiff, InverseReproducesTheDirections) {
  CounterRng rng(3, 0);
  for (int i = 0; i < 2000; ++i) {
    const Vec3d wi = sampleUniformHemisphere(rng.uniform2D()), wo = sampleUniformHemisphere(rng.uniform2D());
    const HalfDiff hd = halfDiffFromDirections(wi, wo);
    const auto [wi2, wo2] = directionsFromHalfDiff(hd.thetaHalf, hd.phiHalf, hd.thetaDiff, hd.phiDiff);
    EXPECT_LT(glm::length(wi2 - wi), 1e-12);
    EXPECT_LT(glm::length(wo2 - wo), 1e-12);
    const auto [cosI, cosO] = polarCosinesFromHalfDiff(hd.thetaHalf, hd.thetaDiff, hd.phiDiff);
    EXPECT_NEAR(cosI, wi.z, 1e-12);
    EXPECT_NEAR(cosO, wo.z, 1e-12);
  }
}

TEST(HalfDiff, MatchesTheDefinitionAtAKnownPair) {
  // wi and wo symmetric about the normal in the x-z plane: h = z, d = wi.
  const double s = std::sin(radians(40.0)), c = std::cos(radians(40.0));
  const Vec3d wi(s, 0, c), wo(-s, 0, c);  // exactly: sin(pi) in directionFromDegrees would tilt h
  const HalfDiff hd = halfDiffFromDirections(wi, wo);
  EXPECT_NEAR(hd.thetaHalf, 0.0, 1e-15);
  EXPECT_NEAR(hd.thetaDiff, radians(40.0), 1e-14);
  EXPECT_NEAR(hd.phiDiff, 0.0, 1e-14);
  // Tilting the pair by 10 degrees about y tilts h by 10 degrees and leaves d as it was.
  const Vec3d wi2 = directionFromDegrees(50, 0), wo2 = directionFromDegrees(30, 180);
  const HalfDiff tilted = halfDiffFromDirections(wi2, wo2);
  EXPECT_NEAR(tilted.thetaHalf, radians(10.0), 1e-14);
  EXPECT_NEAR(tilted.phiHalf, 0.0, 1e-14);
  EXPECT_NEAR(tilted.thetaDiff, radians(40.0), 1e-14);
}

TEST(HalfDiff, SwappingTheDirectionsMovesPhiDiffByPi) {
  CounterRng rng(4, 0);
  for (int i = 0; i < 1000; ++i) {
    const Vec3d wi = sampleUniformHemisphere(rng.uniform2D()), wo = sampleUniformHemisphere(rng.uniform2D());
    const HalfDiff a = halfDiffFromDirections(wi, wo), b = halfDiffFromDirections(wo, wi);
    EXPECT_NEAR(a.thetaDiff, b.thetaDiff, 1e-12);
    EXPECT_NEAR(merl::foldPhiDiff(a.phiDiff), merl::foldPhiDiff(b.phiDiff), 1e-9);
  }
}

// ---- Round trip -----------------------------------------------------------------------------

TEST(MerlIo, WriteThenReadIsBitExact) {
  static_assert(std::endian::native == std::endian::little, "handWrittenFile assumes a little-endian host");
  const MerlTable table = variedTable();
  const fs::path path = scratchPath("roundtrip") += ".binary";
  writeMerl(path, table);
  EXPECT_EQ(fs::file_size(path), merl::FileBytes);
  const std::string bytes = readBytes(path);
  const std::vector<double> stored(table.storedData().begin(), table.storedData().end());
  EXPECT_TRUE(bytes == handWrittenFile(stored)) << "the file is not header + channel-planar doubles";
  const MerlTable back = readMerl(path);
  EXPECT_TRUE(back == table);
  EXPECT_EQ(back.missingCount(), 3u);
  fs::remove(path);
}

TEST(MerlIo, ReadThenWriteReproducesTheFileByteForByte) {
  std::vector<double> stored(3 * merl::CellCount);
  CounterRng rng(11, 0);
  for (double& x : stored) x = rng.uniform() < 0.01 ? -1.0 : rng.uniform() * 3000.0;
  stored[42] = -0.0;  // a signed zero survives too
  const fs::path in = scratchPath("handmade"), out = scratchPath("rewritten");
  writeBytes(in, handWrittenFile(stored));
  const MerlTable table = readMerl(in);
  EXPECT_DOUBLE_EQ(table.value(1, merl::cellIndex(3, 4, 5)),
                   stored[merl::CellCount + merl::cellIndex(3, 4, 5)] * 1.15 / 1500.0);
  writeMerl(out, table);
  EXPECT_TRUE(readBytes(in) == readBytes(out));
  fs::remove(in);
  fs::remove(out);
}

// ---- Bad files --------------------------------------------------------------------------------

TEST(MerlIo, MissingFileAndDirectoryAreNamed) {
  const fs::path missing = scratchPath("absent");
  expectMentions(readErrorOf(missing), {missing.string(), "not found"});
  const fs::path dir = scratchPath("dir");
  fs::create_directories(dir);
  expectMentions(readErrorOf(dir), {dir.string(), "is a directory"});
}

TEST(MerlIo, TruncatedFilesAreRejected) {
  const fs::path path = scratchPath("short");
  writeBytes(path, "abc");
  expectMentions(readErrorOf(path), {path.string(), "truncated", "3 bytes", "header"});
  std::string bytes = handWrittenFile(std::vector<double>(3 * merl::CellCount, 1.0));
  bytes.resize(bytes.size() - 8);
  writeBytes(path, bytes);
  expectMentions(readErrorOf(path),
                 {path.string(), "truncated", std::to_string(merl::FileBytes - 8) + " bytes",
                  std::to_string(merl::FileBytes)});
  fs::remove(path);
}

TEST(MerlIo, OversizedFileIsRejected) {
  const fs::path path = scratchPath("long");
  writeBytes(path, handWrittenFile(std::vector<double>(3 * merl::CellCount + 1, 1.0)));
  expectMentions(readErrorOf(path), {path.string(), "wrong size", "8 more"});
  fs::remove(path);
}

TEST(MerlIo, BadHeaderIsRejectedEvenWithTheRightProduct) {
  const fs::path path = scratchPath("header");
  writeBytes(path, handWrittenFile(std::vector<double>(3 * merl::CellCount, 1.0), {180, 90, 90}));
  expectMentions(readErrorOf(path), {path.string(), "bad header", "180 x 90 x 90", "90 x 90 x 180"});
  writeBytes(path, handWrittenFile(std::vector<double>(12, 1.0), {2, 2, 1}));
  expectMentions(readErrorOf(path), {"bad header", "2 x 2 x 1"});
  fs::remove(path);
}

TEST(MerlIo, NonFiniteValuesAreRejectedWithTheirPlace) {
  std::vector<double> stored(3 * merl::CellCount, 1.0);
  stored[merl::CellCount + merl::cellIndex(2, 3, 4)] = std::nan("");
  stored[2 * merl::CellCount + 9] = -std::numeric_limits<double>::infinity();
  const fs::path path = scratchPath("nan");
  writeBytes(path, handWrittenFile(stored));
  expectMentions(readErrorOf(path),
                 {path.string(), "2 value(s) are NaN or infinite", "green", "theta_h 2, theta_d 3, phi_d 4"});
  fs::remove(path);
}

TEST(MerlIo, NegativeValuesLoadAsMissing) {
  std::vector<double> stored(3 * merl::CellCount, 1.0);
  for (size_t cell : {10u, 20u, 30u})
    for (int c = 0; c < 3; ++c) stored[c * merl::CellCount + cell] = -1.0;
  stored[merl::CellCount + 40] = -2.0;  // one channel alone: the cell is missing too
  const fs::path path = scratchPath("missing");
  writeBytes(path, handWrittenFile(stored));
  const MerlTable table = readMerl(path);
  EXPECT_EQ(table.missingCount(), 4u);
  EXPECT_TRUE(table.isMissing(40));
  EXPECT_FALSE(table.isMissing(41));
  fs::remove(path);
}

TEST(MerlIo, WriterRefusesNonFiniteValuesAndLeavesNothing) {
  MerlTable table;
  table.setStored(0, 3, std::numeric_limits<double>::infinity());
  const fs::path path = scratchPath("refused");
  try {
    writeMerl(path, table);
    FAIL() << "no error";
  } catch (const MerlError& error) {
    expectMentions(error.what(), {path.string(), "not written", "red", "cell 3"});
  }
  EXPECT_FALSE(fs::exists(path));
}

TEST(MerlIo, WriterNamesAMissingDirectory) {
  const fs::path path = scratchPath("nodir") / "table.binary";
  try {
    writeMerl(path, MerlTable());
    FAIL() << "no error";
  } catch (const MerlError& error) {
    expectMentions(error.what(), {path.string(), "does not exist"});
  }
}

}  // namespace merl_io_test
}  // namespace scatterlab
