// The libFuzzer entry point of one target; SCATTERLAB_FUZZ_HARNESS names its harness function
// (fuzz/harness/harness.h), set by scatterlab_fuzz_target() in fuzz/CMakeLists.txt.
#include <cstddef>
#include <cstdint>

#include "fuzz/harness/harness.h"

namespace scatterlab::fuzz {
void SCATTERLAB_FUZZ_HARNESS(Input data);
}  // namespace scatterlab::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  scatterlab::fuzz::SCATTERLAB_FUZZ_HARNESS({data, size});
  return 0;
}
