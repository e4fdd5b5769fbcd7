// Reading and writing MERL BRDF files (layout in merl_format.h). A MerlTable keeps the doubles
// exactly as stored, so read -> write reproduces a file bit for bit; values in sr^-1 are the
// stored numbers times the channel scale.
#pragma once

#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "materials/core/math.h"
#include "materials/measured/merl_format.h"

namespace scatterlab {

// A file that cannot be read or written as a MERL table; the message names the file and the
// problem ("truncated: ...", "bad header: ...", "not found").
class MerlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class MerlTable {
 public:
  MerlTable() : stored_(3 * merl::CellCount, 0.0) {}

  // As in the file: before the channel scale, negative when missing.
  double stored(int channel, size_t cell) const { return stored_[size_t(channel) * merl::CellCount + cell]; }
  void setStored(int channel, size_t cell, double value) {
    stored_[size_t(channel) * merl::CellCount + cell] = value;
  }
  // The BRDF value in sr^-1 (meaningless for a missing cell).
  double value(int channel, size_t cell) const {
    return stored(channel, cell) * merl::ChannelScale[size_t(channel)];
  }
  void setValue(int channel, size_t cell, double f) {
    setStored(channel, cell, f / merl::ChannelScale[size_t(channel)]);
  }
  Rgb rgb(size_t cell) const { return {value(0, cell), value(1, cell), value(2, cell)}; }
  void setRgb(size_t cell, const Rgb& f) {
    for (int c = 0; c < 3; ++c) setValue(c, cell, f[c]);
  }

  // A cell is missing when any channel is negative (MERL writes -1 in all three).
  bool isMissing(size_t cell) const {
    return stored(0, cell) < 0 || stored(1, cell) < 0 || stored(2, cell) < 0;
  }
  void setMissing(size_t cell) {
    for (int c = 0; c < 3; ++c) setStored(c, cell, merl::MissingValue);
  }
  size_t missingCount() const;

  // Channel-planar, 3 x CellCount.
  std::span<const double> storedData() const { return stored_; }
  std::span<double> storedData() { return stored_; }

  bool operator==(const MerlTable&) const = default;

 private:
  std::vector<double> stored_;
};

// Throws MerlError naming `path` and the problem: not found, a directory, not readable,
// truncated or oversized (the size is fixed; checked before reading), a header other than
// 90 x 90 x 180, a NaN, infinite or absurdly large value (above 1e6 sr^-1; the first one's
// channel and cell, and how many), or no valid cell (every cell missing or below the horizon).
MerlTable readMerl(const std::filesystem::path& path);

// readMerl's checks on a file's bytes, already in memory (`path` names it in messages).
MerlTable parseMerl(std::span<const unsigned char> bytes, const std::filesystem::path& path);

// The value checks alone: throws MerlError on a NaN, infinite or absurdly large value.
// `stored` is channel-planar (3 x CellCount, or a part of it from the start).
void checkMerlValues(std::span<const double> stored, const std::filesystem::path& path);
// True when the file at `path` can be opened and starts with the MERL header (int32 90, 90,
// 180, little-endian): format detection by content, whatever the rest of the file holds.
bool isMerlFile(const std::filesystem::path& path);

// Writes atomically (temporary file, then rename): a failure leaves no file behind. Throws
// MerlError if the directory does not exist or cannot be written, or if a value is not
// finite or too large (the reader would reject the file).
void writeMerl(const std::filesystem::path& path, const MerlTable& table);

}  // namespace scatterlab
