// `scatterlab explore` end to end: the page, its scripts and the WebAssembly module are written
// from the executable alone, the given materials are preloaded with their tables embedded
// byte for byte, and bad input writes nothing. The browser test (tests/report/explorer_test.mjs)
// runs the page in Chromium.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/explorer/explorer_page.h"
#include "cli_runner.h"
#include "materials/bsdf/lambertian.h"
#include "materials/measured/measurement_synthesis.h"
#include "materials/measured/merl_io.h"

namespace scatterlab {
namespace explore_cli_test {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace cli_runner;

// The JSON value assigned in `script` ("... = VALUE;" up to its last semicolon).
json assignedJson(const std::string& script) {
  const size_t start = script.find("= ");
  const size_t end = script.rfind(';');
  return json::parse(script.substr(start + 2, end - start - 2));
}

std::string decodeBase64(const std::string& text) {
  static const std::string Alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  uint32_t buffer = 0;
  int bits = 0;
  for (const char c : text) {
    if (c == '=') break;
    buffer = buffer << 6 | uint32_t(Alphabet.find(c));
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += char((buffer >> bits) & 0xFF);
    }
  }
  return out;
}

TEST(ExploreCli, HelpListsEveryOption) {
  const ProcessResult run = runScatterlab({"explore", "--help"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"--out", "--json", "WebAssembly", "material"});
}

// RFC 4648's test vectors (section 10).
TEST(ExploreCli, Base64IsRfc4648) {
  const std::pair<const char*, const char*> vectors[] = {{"", ""},
                                                         {"f", "Zg=="},
                                                         {"fo", "Zm8="},
                                                         {"foo", "Zm9v"},
                                                         {"foob", "Zm9vYg=="},
                                                         {"fooba", "Zm9vYmE="},
                                                         {"foobar", "Zm9vYmFy"}};
  for (const auto& [text, encoded] : vectors) EXPECT_EQ(base64(text), encoded) << text;
  const std::string bytes{'\0', '\xff', '\x10', '\x80'};
  EXPECT_EQ(decodeBase64(base64(bytes)), bytes);
}

TEST(ExploreCli, WritesThePageWithTheGivenMaterialsAndTheirTables) {
  const LambertianBsdf lambert(Rgb(0.3, 0.5, 0.7));
  const fs::path table = uniquePath("white.binary");
  writeMerl(table, MeasurementSynthesizer({&lambert}, {}).synthesize());
  const fs::path materialFile = uniquePath("gold.json");
  std::ofstream(materialFile) << R"({"type": "conductor", "metal": "Au"})";
  const fs::path out = uniquePath("explorer");
  const ProcessResult run =
      runScatterlab({"explore", table.string(), materialFile.string(),
                     R"({"type": "blend", "materials": [{"type": "measured", "file": ")" + table.string() +
                         R"("}, {"type": "lambertian"}]})",
                     "--out", out.string(), "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json summary = json::parse(run.out);
  EXPECT_EQ(summary["index"], (out / "index.html").string());
  ASSERT_EQ(summary["materials"].size(), 3u);
  EXPECT_EQ(summary["written"]["tables"], 1);  // the table given twice is embedded once

  for (const char* file :
       {"index.html", "assets/scatterlab-api.js", "assets/explorer-plots.js", "assets/explorer.js",
        "assets/explorer.css", "assets/scatterlab-wasm.js", "explorer.json"})
    EXPECT_TRUE(fs::is_regular_file(out / file)) << file;
  expectMentions(readFile(out / "index.html"),
                 {"assets/scatterlab-wasm.js", "assets/explorer.js", "error-box"});
  // The module is one JavaScript file holding the WebAssembly (SINGLE_FILE): no .wasm beside it.
  expectMentions(readFile(out / "assets" / "scatterlab-wasm.js"), {"createScatterlabModule"});
  EXPECT_FALSE(fs::exists(out / "assets" / "scatterlab-wasm.wasm"));

  const json preload = assignedJson(readFile(out / "assets" / "preload.js"))["materials"];
  ASSERT_EQ(preload.size(), 3u);
  EXPECT_EQ(preload[0]["id"], table.filename().string());
  EXPECT_EQ(preload[0]["material"]["type"], "measured");
  const std::string embeddedPath = preload[0]["material"]["file"];
  EXPECT_EQ(preload[1]["material"], json::parse(R"({"type": "conductor", "metal": "Au"})"));
  EXPECT_EQ(preload[2]["material"]["materials"][0]["file"], embeddedPath);
  ASSERT_EQ(preload[0]["tables"].size(), 1u);
  const fs::path script = out / preload[0]["tables"][0]["script"].get<std::string>();
  const std::string text = readFile(script);
  const size_t quote = text.find("=\n\"");
  ASSERT_NE(quote, std::string::npos);
  EXPECT_NE(text.find(json(embeddedPath).dump()), std::string::npos);
  EXPECT_EQ(decodeBase64(text.substr(quote + 3, text.rfind('"') - quote - 3)), readFile(table));
}

TEST(ExploreCli, BadInputWritesNothing) {
  const fs::path out = uniquePath("explorer-bad");
  expectBadInput({"explore", R"({"type": "conductor", "alpha": 2})", "--out", out.string()},
                 {"\"alpha\"", "[0.001, 1]"});
  const fs::path broken = uniquePath("broken.binary");
  std::ofstream(broken) << "not a table";
  expectBadInput({"explore", broken.string(), "--out", out.string()}, {broken.string(), "\"file\""});
  EXPECT_FALSE(fs::exists(out));
  expectBadInput({"explore"}, {"--out"});
  // An existing directory that is not an explorer is never replaced.
  fs::create_directories(out);
  std::ofstream(out / "notes.txt") << "mine";
  expectBadInput({"explore", "--out", out.string()}, {"--out", out.string()});
  EXPECT_EQ(readFile(out / "notes.txt"), "mine");
}

TEST(ExploreCli, ASecondExplorerReplacesTheFirst) {
  const fs::path out = uniquePath("explorer-again");
  ASSERT_EQ(runScatterlab({"explore", R"({"type": "lambertian"})", "--out", out.string()}).exitCode, 0);
  const ProcessResult again = runScatterlab({"explore", "--out", out.string()});
  ASSERT_EQ(again.exitCode, 0) << describe(again);
  expectMentions(again.out, {"0 given materials", "index.html"});
  EXPECT_TRUE(assignedJson(readFile(out / "assets" / "preload.js"))["materials"].empty());
}

}  // namespace explore_cli_test
}  // namespace scatterlab
