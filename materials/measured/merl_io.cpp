#include "materials/measured/merl_io.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "materials/core/atomic_file.h"
#include "materials/core/bounded_file.h"
#include "materials/measured/tabulated_brdf.h"  // isReachableCell

namespace scatterlab {

namespace {

namespace fs = std::filesystem;

constexpr std::array<int32_t, 3> Dimensions{merl::ThetaHalfCells, merl::ThetaDiffCells, merl::PhiDiffCells};
constexpr std::array<const char*, 3> ChannelNames{"red", "green", "blue"};

[[noreturn]] void fail(const fs::path& path, const std::string& problem) {
  throw MerlError("MERL file \"" + path.string() + "\": " + problem);
}

std::string expectedLayout() {
  return "a MERL file has " + std::to_string(merl::FileBytes) +
         " bytes: a 12-byte header (90, 90, 180) and 3 x " + std::to_string(merl::CellCount) + " float64";
}

// The file is little-endian; on a big-endian host every word is byte-swapped.
template <typename T> void fromLittleEndian(std::span<T> words) {
  if constexpr (std::endian::native == std::endian::big) {
    for (T& word : words) {
      unsigned char bytes[sizeof(T)];
      std::memcpy(bytes, &word, sizeof(T));
      std::reverse(bytes, bytes + sizeof(T));
      std::memcpy(&word, bytes, sizeof(T));
    }
  }
}

std::string describeCell(size_t cell) {
  const merl::CellCoordinates c = merl::cellCoordinates(cell);
  return "cell " + std::to_string(cell) + " (theta_h " + std::to_string(c.thetaHalf) + ", theta_d " +
         std::to_string(c.thetaDiff) + ", phi_d " + std::to_string(c.phiDiff) + ")";
}

// The first non-finite value and how many there are, or an empty string.
std::string nonFiniteValues(std::span<const double> stored) {
  size_t count = 0, first = 0;
  for (size_t i = 0; i < stored.size(); ++i) {
    if (std::isfinite(stored[i])) continue;
    if (count++ == 0) first = i;
  }
  if (count == 0) return "";
  const double value = stored[first];
  const std::string what = std::isnan(value) ? "NaN" : (value > 0 ? "inf" : "-inf");
  return std::to_string(count) + " value(s) are NaN or infinite, the first " + what + " in the " +
         ChannelNames[std::min<size_t>(first / merl::CellCount, 2)] + " channel at " +
         describeCell(first % merl::CellCount);
}

}  // namespace

size_t MerlTable::missingCount() const {
  size_t count = 0;
  for (size_t cell = 0; cell < merl::CellCount; ++cell) count += isMissing(cell) ? 1 : 0;
  return count;
}

bool isMerlFile(const fs::path& path) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) return false;
  std::ifstream file(path, std::ios::binary);
  std::array<int32_t, 3> header{};
  if (!file.read(reinterpret_cast<char*>(header.data()), merl::HeaderBytes)) return false;
  fromLittleEndian(std::span<int32_t>(header));
  return header == Dimensions;
}

namespace {

// Values far above any measured BRDF: a mirror seen in one 1-degree cell is about 1e4 sr^-1
// (1 / (cos theta x solid angle)), and sums of squares over every cell of 1e6 stay finite, so
// the fits and renders of a table cannot overflow.
constexpr double MaxBrdfValue = 1e6;

// The first value above MaxBrdfValue and how many there are, or an empty string.
std::string hugeValues(std::span<const double> stored) {
  size_t count = 0, first = 0;
  for (size_t i = 0; i < stored.size(); ++i) {
    if (!(stored[i] * merl::ChannelScale[std::min<size_t>(i / merl::CellCount, 2)] > MaxBrdfValue)) continue;
    if (count++ == 0) first = i;
  }
  if (count == 0) return "";
  const size_t channel = std::min<size_t>(first / merl::CellCount, 2);
  return std::to_string(count) + " value(s) exceed " + std::to_string(int(MaxBrdfValue)) +
         " sr^-1, the first " + std::to_string(stored[first] * merl::ChannelScale[channel]) + " in the " +
         ChannelNames[channel] + " channel at " + describeCell(first % merl::CellCount) +
         "; allowed: values up to " + std::to_string(int(MaxBrdfValue)) + " sr^-1 (a mirror reaches 1e4)";
}

// Empty when some cell is measured and above the horizon, else why the table holds nothing.
std::string nothingUsable(const MerlTable& table) {
  size_t missing = 0;
  for (size_t cell = 0; cell < merl::CellCount; ++cell) {
    if (!table.isMissing(cell) && isReachableCell(cell)) return "";
    missing += table.isMissing(cell) ? 1 : 0;
  }
  return "no valid cells: " + std::to_string(missing) + " of " + std::to_string(merl::CellCount) +
         " missing (negative), the rest below the horizon; allowed: a table with a measured cell";
}

}  // namespace

MerlTable parseMerl(std::span<const unsigned char> bytes, const fs::path& path) {
  const size_t size = bytes.size();
  if (size < merl::HeaderBytes)
    fail(path, "truncated: " + std::to_string(size) + " bytes, shorter than the 12-byte header; " +
                   expectedLayout());
  std::array<int32_t, 3> header{};
  std::memcpy(header.data(), bytes.data(), merl::HeaderBytes);
  fromLittleEndian(std::span<int32_t>(header));
  if (header != Dimensions)
    fail(path, "bad header: dimensions " + std::to_string(header[0]) + " x " + std::to_string(header[1]) +
                   " x " + std::to_string(header[2]) +
                   ", expected 90 x 90 x 180 (theta_h x theta_d x phi_d)");
  if (size < merl::FileBytes)
    fail(path, "truncated: " + std::to_string(size) + " bytes; " + expectedLayout());
  if (size > merl::FileBytes)
    fail(path, "wrong size: " + std::to_string(size) + " bytes, " + std::to_string(size - merl::FileBytes) +
                   " more than the table; " + expectedLayout());
  MerlTable table;
  const std::span<double> stored = table.storedData();
  std::memcpy(stored.data(), bytes.data() + merl::HeaderBytes, stored.size_bytes());
  fromLittleEndian(stored);
  checkMerlValues(stored, path);
  if (const std::string empty = nothingUsable(table); !empty.empty()) fail(path, empty);
  return table;
}

void checkMerlValues(std::span<const double> stored, const fs::path& path) {
  if (const std::string bad = nonFiniteValues(stored); !bad.empty()) fail(path, bad);
  if (const std::string bad = hugeValues(stored); !bad.empty()) fail(path, bad);
}

MerlTable readMerl(const fs::path& path) {
  std::error_code error;
  const auto status = fs::status(path, error);
  if (!fs::exists(status)) fail(path, "not found");
  if (fs::is_directory(status)) fail(path, "is a directory, not a file");
  // The size is known before anything is read: a wrong one is refused at once, and a device
  // or pipe is read up to one table's bytes, never more (bounded_file.h).
  if (fs::is_regular_file(status)) {
    const uintmax_t size = fs::file_size(path, error);
    if (error) fail(path, "not readable (" + error.message() + ")");
    if (size > merl::FileBytes)
      fail(path, "wrong size: " + std::to_string(size) + " bytes, " + std::to_string(size - merl::FileBytes) +
                     " more than the table; " + expectedLayout());
  }
  std::string bytes;
  try {
    bytes = readFileBounded(path, merl::FileBytes, "MERL file");
  } catch (const InputFileError& e) {
    fail(path, e.problem());
  }
  return parseMerl({reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()}, path);
}

void writeMerl(const fs::path& path, const MerlTable& table) {
  if (const std::string bad = nonFiniteValues(table.storedData()); !bad.empty())
    fail(path, "not written: " + bad);
  if (const std::string bad = hugeValues(table.storedData()); !bad.empty()) fail(path, "not written: " + bad);
  std::error_code error;
  if (fs::is_directory(path, error)) fail(path, "not written: is a directory");
  const fs::path directory = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  if (!fs::is_directory(directory, error))
    fail(path, "not written: directory \"" + directory.string() + "\" does not exist");
  try {
    writeFileAtomically(path, [&](const fs::path& temporary) {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      if (!out)
        fail(path, std::string("not written: cannot create a file in its directory (") +
                       std::strerror(errno) + ")");
      std::array<int32_t, 3> header = Dimensions;
      fromLittleEndian(std::span<int32_t>(header));  // the same swap converts to little-endian
      out.write(reinterpret_cast<const char*>(header.data()), merl::HeaderBytes);
      if constexpr (std::endian::native == std::endian::big) {
        std::vector<double> swapped(table.storedData().begin(), table.storedData().end());
        fromLittleEndian(std::span<double>(swapped));
        out.write(reinterpret_cast<const char*>(swapped.data()),
                  std::streamsize(swapped.size() * sizeof(double)));
      } else {
        const std::span<const double> stored = table.storedData();
        out.write(reinterpret_cast<const char*>(stored.data()), std::streamsize(stored.size_bytes()));
      }
      out.close();
      if (!out) fail(path, std::string("not written: write failed (") + std::strerror(errno) + ")");
    });
  } catch (const fs::filesystem_error& e) {
    fail(path, std::string("not written: ") + e.code().message());
  }
}

}  // namespace scatterlab
