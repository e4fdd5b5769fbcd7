// The MERL layout against the conventions of the database's published reader (BRDFRead.cpp of
// Matusik et al. 2003; docs/references.md, "MERL BRDF binary format"), computed here from
// those conventions alone, without the project's merl_format.h: a direction pair gives the
// reader's half/difference angles (its two rotations of wi), then its cell, with theta_h
// indexed by sqrt(theta_h / (pi/2)) * 90 and phi_d folded into [0, pi) by reciprocity, then
// the value, the stored double of that cell times the channel's scale (1, 1.15, 1.66) / 1500,
// green and blue 1,458,000 and 2,916,000 doubles after red.
//
// A file is written byte by byte with a different value in every cell, read by readMerl, and
// evaluated by TabulatedBrdf at pairs whose angles are the cell centres (where its trilinear
// interpolation is the cell's value): ten pairs, near the highlight where the square-root
// index matters most, at grazing theta_d, with phi_d negative before folding, and with wi and
// wo swapped.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "materials/measured/tabulated_brdf.h"
#include "measured_test_support.h"

namespace scatterlab {
namespace merl_reference_test {

constexpr double ReaderPi = std::numbers::pi;
constexpr int ThetaHalfRes = 90, ThetaDiffRes = 90, PhiDiffRes = 180;
constexpr size_t Cells = size_t(ThetaHalfRes) * ThetaDiffRes * PhiDiffRes;
constexpr std::array<double, 3> Scale{1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};

// A different stored value in every cell and channel, all positive (none missing).
double storedValue(int channel, size_t cell) {
  return 1.0 + double((cell * 2654435761u + size_t(channel) * 40503u) % 1000003u) / 97.0;
}

using Vector = std::array<double, 3>;

// The reader's rotation of v about a unit axis by angle (Rodrigues' formula).
Vector rotate(const Vector& v, const Vector& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const double dot = v[0] * axis[0] + v[1] * axis[1] + v[2] * axis[2];
  const Vector cross{axis[1] * v[2] - axis[2] * v[1], axis[2] * v[0] - axis[0] * v[2],
                     axis[0] * v[1] - axis[1] * v[0]};
  Vector out;
  for (int k = 0; k < 3; ++k)
    out[size_t(k)] = v[size_t(k)] * c + axis[size_t(k)] * dot * (1 - c) + cross[size_t(k)] * s;
  return out;
}

Vector normalised(const Vector& v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

struct ReferenceCell {
  int thetaHalf, thetaDiff, phiDiff;
  size_t index;
};

// The reader's lookup of the pair (wi, wo): half vector, then d = wi rotated by -phi_h about the
// normal and by -theta_h about the binormal; then its three indices. `fold` false: phi_d is
// not folded (what a reader without reciprocity would do; clamped to the first cell).
ReferenceCell referenceCell(const Vector& wi, const Vector& wo, bool fold = true) {
  const Vector half = normalised({wi[0] + wo[0], wi[1] + wo[1], wi[2] + wo[2]});
  const double thetaHalf = std::acos(half[2]), phiHalf = std::atan2(half[1], half[0]);
  const Vector d = rotate(rotate(wi, {0, 0, 1}, -phiHalf), {0, 1, 0}, -thetaHalf);
  const double thetaDiff = std::acos(d[2]);
  double phiDiff = std::atan2(d[1], d[0]);
  ReferenceCell cell{};
  // theta_h: sqrt(theta_h in degrees * 90), clamped to [0, 89]; 0 for theta_h <= 0.
  cell.thetaHalf =
      thetaHalf <= 0 ? 0 : std::min(int(std::sqrt(thetaHalf / (ReaderPi / 2) * 90 * 90)), ThetaHalfRes - 1);
  cell.thetaDiff = std::clamp(int(thetaDiff / (ReaderPi / 2) * ThetaDiffRes), 0, ThetaDiffRes - 1);
  if (fold && phiDiff < 0) phiDiff += ReaderPi;  // reciprocity
  cell.phiDiff = std::clamp(int(phiDiff / ReaderPi * PhiDiffRes), 0, PhiDiffRes - 1);
  cell.index = size_t(cell.phiDiff) + size_t(cell.thetaDiff) * PhiDiffRes +
               size_t(cell.thetaHalf) * PhiDiffRes * ThetaDiffRes;
  return cell;
}

// The pair at the centre of cell (th, td, pd), written from the reader's angles: d at
// (theta_d, phi_d), wi = R_z(phi_h) R_y(theta_h) d and wo the same of d mirrored about the
// pole. `unfolded`: phi_d taken pi below the centre (negative), which the reader folds back.
std::array<Vector, 2> pairAtCentre(int th, int td, int pd, double phiHalf, bool unfolded) {
  const double thetaHalf = std::pow((th + 0.5) / ThetaHalfRes, 2) * ReaderPi / 2;
  const double thetaDiff = (td + 0.5) / ThetaDiffRes * ReaderPi / 2;
  const double phiDiff = (pd + 0.5) / PhiDiffRes * ReaderPi - (unfolded ? ReaderPi : 0.0);
  const Vector d{std::sin(thetaDiff) * std::cos(phiDiff), std::sin(thetaDiff) * std::sin(phiDiff),
                 std::cos(thetaDiff)};
  const auto toWorld = [&](const Vector& v) {
    return rotate(rotate(v, {0, 1, 0}, thetaHalf), {0, 0, 1}, phiHalf);
  };
  return {toWorld(d), toWorld({-d[0], -d[1], d[2]})};
}

struct Case {
  const char* what;
  int thetaHalf, thetaDiff, phiDiff;
  double phiHalf;
  bool unfolded, swapped;
};

const std::vector<Case>& cases() {
  static const std::vector<Case> c{
      {"at the highlight", 0, 10, 20, 0.3, false, false},
      {"second theta_h cell (0.025 deg)", 1, 30, 90, 1.2, false, false},
      {"fourth theta_h cell", 3, 45, 5, -2.0, true, false},
      {"theta_h 10 deg", 30, 20, 150, 0.0, false, true},
      {"theta_h 40 deg", 60, 10, 100, 2.5, true, false},
      {"theta_h 71 deg", 80, 5, 45, -0.7, false, false},
      {"grazing theta_d", 5, 85, 2, 1.0, false, false},
      {"last phi_d cell", 12, 40, 179, 0.4, false, true},
      {"first phi_d cell, folded", 20, 60, 0, -1.4, true, true},
      {"theta_d 45, phi_d 90", 45, 45, 89, 3.0, false, false},
  };
  return c;
}

class MerlReference : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::vector<double> stored(3 * Cells);
    for (int c = 0; c < 3; ++c)
      for (size_t i = 0; i < Cells; ++i) stored[size_t(c) * Cells + i] = storedValue(c, i);
    const int32_t header[3] = {ThetaHalfRes, ThetaDiffRes, PhiDiffRes};
    const auto path = measured_test::scratchPath("reference") += ".binary";
    {
      std::ofstream out(path, std::ios::binary);
      out.write(reinterpret_cast<const char*>(header), sizeof header);  // little-endian host
      out.write(reinterpret_cast<const char*>(stored.data()),
                std::streamsize(stored.size() * sizeof(double)));
    }
    brdf_ = new TabulatedBrdf(readMerl(path));
    std::filesystem::remove(path);
  }
  static void TearDownTestSuite() {
    delete brdf_;
    brdf_ = nullptr;
  }
  static TabulatedBrdf* brdf_;
};
TabulatedBrdf* MerlReference::brdf_ = nullptr;

TEST_F(MerlReference, TenPairsReadTheCellThePublishedReaderReads) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.what);
    auto [wi, wo] = pairAtCentre(c.thetaHalf, c.thetaDiff, c.phiDiff, c.phiHalf, c.unfolded);
    if (c.swapped) std::swap(wi, wo);
    ASSERT_GT(wi[2], 0.0);
    ASSERT_GT(wo[2], 0.0);
    // Direction pair -> the reader's cell: the cell whose centre the pair was built at.
    const ReferenceCell cell = referenceCell(wi, wo);
    EXPECT_EQ(cell.thetaHalf, c.thetaHalf);
    EXPECT_EQ(cell.thetaDiff, c.thetaDiff);
    EXPECT_EQ(cell.phiDiff, c.phiDiff);
    // Cell -> value, and the project's reader and evaluation give the same (float storage:
    // 2^-24 relative).
    const Rgb f = brdf_->eval(Vec3d(wi[0], wi[1], wi[2]), Vec3d(wo[0], wo[1], wo[2]));
    for (int ch = 0; ch < 3; ++ch) {
      const double expected = storedValue(ch, cell.index) * Scale[size_t(ch)];
      EXPECT_NEAR(f[ch], expected, 1e-6 * expected) << "channel " << ch << ", cell " << cell.index;
    }
  }
}

// The test's power: a reader that indexed theta_h linearly (theta_h / (pi/2) * 90), or did not
// fold phi_d, would read another cell for most of these pairs, whose value is not the one
// evaluated.
TEST_F(MerlReference, ALinearThetaHalfIndexOrAnUnfoldedPhiDiffReadsAnotherValue) {
  int linearDiffers = 0, unfoldedDiffers = 0;
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.what);
    auto [wi, wo] = pairAtCentre(c.thetaHalf, c.thetaDiff, c.phiDiff, c.phiHalf, c.unfolded);
    if (c.swapped) std::swap(wi, wo);
    const ReferenceCell cell = referenceCell(wi, wo);
    const double red = brdf_->eval(Vec3d(wi[0], wi[1], wi[2]), Vec3d(wo[0], wo[1], wo[2]))[0];
    const double thetaHalf = std::pow((c.thetaHalf + 0.5) / ThetaHalfRes, 2) * ReaderPi / 2;
    const int linear = std::min(int(thetaHalf / (ReaderPi / 2) * ThetaHalfRes), ThetaHalfRes - 1);
    if (linear != cell.thetaHalf) {
      const size_t wrong = size_t(cell.phiDiff) + size_t(cell.thetaDiff) * PhiDiffRes +
                           size_t(linear) * PhiDiffRes * ThetaDiffRes;
      EXPECT_GT(std::abs(red - storedValue(0, wrong) * Scale[0]), 1e-3 * red);
      ++linearDiffers;
    }
    const ReferenceCell unfolded = referenceCell(wi, wo, /*fold=*/false);
    if (unfolded.index != cell.index) {
      EXPECT_GT(std::abs(red - storedValue(0, unfolded.index) * Scale[0]), 1e-3 * red);
      ++unfoldedDiffers;
    }
  }
  EXPECT_GE(linearDiffers, 8);
  EXPECT_GE(unfoldedDiffers, 3);
}

}  // namespace merl_reference_test
}  // namespace scatterlab
