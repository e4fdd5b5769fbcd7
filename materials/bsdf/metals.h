// Named metals: complex refractive index eta + i k per linear-RGB channel, for the conductor
// model ({"type": "conductor", "metal": "Au"}). The numbers are a constant table (the binary
// reads no data files); data/ior/README.md states where they come from and how they were
// reduced from the measured spectra, and tests/materials/bsdf/metals_test.cpp recomputes them
// from data/ior/*.spd with reduceMetalSpectra (metal_reduction.h).
#pragma once

#include <span>
#include <string_view>

#include "materials/core/math.h"

namespace scatterlab {

struct MetalIor {
  const char* name;  // chemical symbol: "Au", "Ag", "Al", "Cu", "Cr"
  Rgb eta;           // real part of the index, per channel
  Rgb k;             // extinction coefficient, per channel
};

std::span<const MetalIor> namedMetals();

// The metal with this exact (case-sensitive) symbol, or nullptr.
const MetalIor* findMetal(std::string_view name);

}  // namespace scatterlab
