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
         ChannelNames[first / merl::CellCount] + " channel at " + describeCell(first % merl::CellCount);
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

MerlTable readMerl(const fs::path& path) {
  std::error_code error;
  const auto status = fs::status(path, error);
  if (!fs::exists(status)) fail(path, "not found");
  if (fs::is_directory(status)) fail(path, "is a directory, not a file");
  std::ifstream file(path, std::ios::binary);
  if (!file) fail(path, std::string("not readable (") + std::strerror(errno) + ")");
  const uintmax_t size = fs::file_size(path, error);
  if (error) fail(path, "not readable (" + error.message() + ")");
  if (size < merl::HeaderBytes)
    fail(path, "truncated: " + std::to_string(size) + " bytes, shorter than the 12-byte header; " +
                   expectedLayout());

  std::array<int32_t, 3> header{};
  if (!file.read(reinterpret_cast<char*>(header.data()), merl::HeaderBytes))
    fail(path, "header not readable");
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
  if (!file.read(reinterpret_cast<char*>(stored.data()), std::streamsize(stored.size_bytes())))
    fail(path, "truncated while reading (" + std::to_string(file.gcount()) + " of " +
                   std::to_string(stored.size_bytes()) + " data bytes read)");
  fromLittleEndian(stored);
  if (const std::string bad = nonFiniteValues(stored); !bad.empty()) fail(path, bad);
  return table;
}

void writeMerl(const fs::path& path, const MerlTable& table) {
  if (const std::string bad = nonFiniteValues(table.storedData()); !bad.empty())
    fail(path, "not written: " + bad);
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
