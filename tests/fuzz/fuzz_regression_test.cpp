// Every fuzz harness (fuzz/harness/harness.h) on its saved corpus and on every input a
// fuzzer ever found to crash it (fuzz/regressions/NAME): each must now be refused or handled
// without a crash, a sanitizer report or a non-finite value. Runs in the release and the
// sanitizer test passes, so a past finding cannot come back.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string>
#include <vector>

#include "fuzz/harness/harness.h"

namespace scatterlab::fuzz {
namespace fuzz_regression_test {

namespace fs = std::filesystem;

const fs::path FuzzDir = fs::path(SCATTERLAB_DATA_DIR).parent_path() / "fuzz";

std::vector<fs::path> inputsIn(const fs::path& directory) {
  std::vector<fs::path> files;
  std::error_code error;
  for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error))
    if (it->is_regular_file()) files.push_back(it->path());
  return files;
}

std::vector<uint8_t> bytesOf(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace fuzz_regression_test

// The harness's name in gtest's messages.
void PrintTo(const FuzzHarness& harness, std::ostream* out) { *out << harness.name; }

namespace fuzz_regression_test {

class FuzzHarnessInputs : public ::testing::TestWithParam<FuzzHarness> {};

TEST_P(FuzzHarnessInputs, SeedCorpusRunsCleanly) {
  const std::vector<fs::path> seeds = inputsIn(FuzzDir / "corpus" / GetParam().name);
  EXPECT_FALSE(seeds.empty()) << "no seed inputs in fuzz/corpus/" << GetParam().name;
  for (const fs::path& seed : seeds) {
    SCOPED_TRACE(seed.string());
    const std::vector<uint8_t> bytes = bytesOf(seed);
    GetParam().run(bytes);
  }
}

TEST_P(FuzzHarnessInputs, PastFindingsStayFixed) {
  for (const fs::path& finding : inputsIn(FuzzDir / "regressions" / GetParam().name)) {
    SCOPED_TRACE(finding.string());
    const std::vector<uint8_t> bytes = bytesOf(finding);
    GetParam().run(bytes);
  }
}

INSTANTIATE_TEST_SUITE_P(Harness, FuzzHarnessInputs, ::testing::ValuesIn(fuzzHarnesses()),
                         [](const ::testing::TestParamInfo<FuzzHarness>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace fuzz_regression_test
}  // namespace scatterlab::fuzz
