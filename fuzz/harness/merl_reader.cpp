// Fuzz harness (fuzz/harness/harness.h): a MERL .binary table (materials/measured/merl_io.h),
// the reader on the bytes, and its value checks on the doubles the bytes hold.
#include <cstring>
#include <vector>

#include "fuzz/harness/harness.h"
#include "materials/measured/merl_io.h"

namespace scatterlab::fuzz {

void merlReader(Input data) {
  try {
    parseMerl(data, "fuzz.binary");
  } catch (const MerlError&) {}
  // A whole table is 35 MB, far beyond what a fuzzer mutates, so the value checks also run on
  // whatever doubles the input holds, as the first cells of the red channel onwards.
  std::vector<double> values(std::min(data.size() / sizeof(double), 3 * merl::CellCount));
  // memcpy from or to a null pointer is undefined even for 0 bytes (an empty vector's data()).
  if (!values.empty()) std::memcpy(values.data(), data.data(), values.size() * sizeof(double));
  try {
    checkMerlValues(values, "fuzz.binary");
  } catch (const MerlError&) {}
}

}  // namespace scatterlab::fuzz
