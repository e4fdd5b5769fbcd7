// The measured media of Jensen et al. 2001 (Figure 5), compiled in: the executable never reads
// data/ at run time. data/media.json holds the same table with its source, and a test checks
// that the two agree entry by entry.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "materials/core/math.h"

namespace scatterlab {

struct MeasuredMedium {
  const char* name;
  Rgb sigmaSPrime;  // reduced scattering coefficient, mm^-1 (measured with g = 0: also sigma_s)
  Rgb sigmaA;       // absorption coefficient, mm^-1
  double eta;       // index of refraction relative to air
};

std::span<const MeasuredMedium> measuredMedia();
const MeasuredMedium* findMeasuredMedium(std::string_view name);
std::vector<std::string> measuredMediumNames();

}  // namespace scatterlab
