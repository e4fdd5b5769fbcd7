#include "materials/bsdf/metals.h"

#include <array>

namespace scatterlab {

namespace {

// Reduced from data/ior/<name>.{eta,k}.spd (Palik via luxpop.com) by reduceMetalSpectra
// (metal_reduction.h; method in data/ior/README.md). metals_test recomputes these from the
// spectra and, on a mismatch, prints replacement lines.
constexpr std::array<MetalIor, 5> Metals{{
    {"Au", {0.2780049333, 0.4699444303, 1.445112442}, {13.08074476, 2.596425247, 1.655904474}},
    {"Ag", {0.1291336665, 0.1261907202, 0.149077464}, {4.002512564, 3.3904244, 2.356566588}},
    {"Al", {1.219239698, 0.92736026, 0.6250532293}, {7.187067956, 6.594948867, 5.522098582}},
    {"Cu", {0.4238309021, 0.95281067, 1.163201182}, {4.829409364, 2.601179284, 2.301282388}},
    {"Cr", {3.383761153, 3.00859264, 1.97540554}, {4.256621175, 4.415294074, 4.237641507}},
}};

}  // namespace

std::span<const MetalIor> namedMetals() { return Metals; }

const MetalIor* findMetal(std::string_view name) {
  for (const MetalIor& metal : Metals)
    if (name == metal.name) return &metal;
  return nullptr;
}

}  // namespace scatterlab
