// The hidden `scatterlab generate-table` command: the committed table file is exactly what its
// formatter writes for the committed values (so the file was produced by the generator, and
// its %.17g values read back to the same doubles), and the command's bad input is rejected
// with exit code 2 and a message, without running the generator.
#include "app/generate_table_command.h"

#include <gtest/gtest.h>

#include "cli_runner.h"
#include "materials/bsdf/white_microfacet_albedo.h"

namespace scatterlab {
namespace generate_table_test {

using namespace cli_runner;

TEST(GenerateTable, CommittedWhiteAlbedoTableIsTheGeneratorsOutput) {
  const fs::path committed =
      fs::path(SCATTERLAB_DATA_DIR).parent_path() / "materials/bsdf/tables/white_microfacet_albedo_table.cpp";
  const std::vector<double> ggx(GgxWhiteAlbedoTable.begin(), GgxWhiteAlbedoTable.end());
  const std::vector<double> beckmann(BeckmannWhiteAlbedoTable.begin(), BeckmannWhiteAlbedoTable.end());
  const std::string command =
      "scatterlab generate-table white-microfacet-albedo --out "
      "materials/bsdf/tables/white_microfacet_albedo_table.cpp";
  EXPECT_EQ(readFile(committed), whiteAlbedoTableSource(ggx, beckmann, command));
}

TEST(GenerateTable, IsHiddenAndRejectsBadInput) {
  const ProcessResult help = runScatterlab({"--help"});
  EXPECT_EQ(help.out.find("generate-table"), std::string::npos) << help.out;
  EXPECT_EQ(runScatterlab({"generate-table", "--help"}).exitCode, 0);
  const ProcessResult unknown = runScatterlab({"generate-table", "no-such-table", "--out", "x.cpp"});
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.err.find("white-microfacet-albedo"), std::string::npos) << unknown.err;
}

// Unwritable outputs are refused before the generator runs (it takes minutes); --output is the
// old name of --out and still works.
TEST(GenerateTable, RefusesUnwritableOutputsBeforeComputing) {
  expectBadInput({"generate-table", "white-microfacet-albedo", "--output", ""}, {"--out: missing"});
  expectBadInput({"generate-table", "white-microfacet-albedo", "--out", "/proc/scatterlab-table.cpp"},
                 {"--out", "cannot write in the directory \"/proc\""});
  expectBadInput({"generate-table", "white-microfacet-albedo", "--out", "/dev/null"},
                 {"--out", "not a regular file"});
  expectBadInput({"generate-table", "white-microfacet-albedo", "--out", uniquePath("dir").string() + "/"},
                 {"--out", "ends in '/'"});
}

}  // namespace generate_table_test
}  // namespace scatterlab
