// JSON that would crash a recursive reader: nesting of any depth, inline and in files, for every
// command that reads a material, is refused with a message naming the limit (exit 2); numbers
// that overflow a double name their key (materials/core/json_text.h).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "cli_runner.h"

namespace scatterlab {
namespace hostile_json_cli_test {

using namespace cli_runner;

std::string nestedArrays(int depth) {
  return std::string(size_t(depth), '[') + std::string(size_t(depth), ']');
}

// {"type":"lambertian","albedo":[[[...]]]}: the deep value sits under a key.
std::string materialWithDeepValue(int depth) {
  return R"({"type":"lambertian","albedo":)" + nestedArrays(depth) + "}";
}

// `levels` blends, each the first component of the next.
std::string nestedBlends(int levels) {
  std::string text;
  for (int i = 0; i < levels; ++i) text += R"({"type":"blend","materials":[)";
  text += R"({"type":"lambertian"})";
  for (int i = 0; i < levels; ++i) text += R"(,{"type":"lambertian"}]})";
  return text;
}

// Every command that reads a material, with the material in `material`.
std::vector<std::vector<std::string>> everyMaterialCommand(const std::string& material) {
  const std::string out = uniquePath("deep-out").string();
  return {{"check", material, "--samples", "1000"},
          {"render", material, "--out", out, "--res", "8", "--spp", "1"},
          {"fit", material, "--model", "lambertian", "--metric", "l2"},
          {"synth", material, "--out", out + ".binary"},
          {"profile", material},
          {"lab", material, "--quick", "--out", out}};
}

TEST(HostileJson, DeepInlineArraysAreRefusedByEveryCommand) {
  for (const auto& args : everyMaterialCommand(materialWithDeepValue(20000))) {
    SCOPED_TRACE(args.front());
    expectBadInput(args, {"inline JSON", "nested more than 64 levels deep"});
  }
}

TEST(HostileJson, DeepArraysInAFileAreRefused) {
  const fs::path file = uniquePath("deep") += ".json";
  std::ofstream(file) << materialWithDeepValue(100000);
  for (const auto& args : everyMaterialCommand(file.string())) {
    SCOPED_TRACE(args.front());
    expectBadInput(args, {file.string(), "nested more than 64 levels deep"});
  }
  fs::remove(file);
}

// In a file: 10,000 blends are about 500 kB, more than one command-line argument may hold.
TEST(HostileJson, TenThousandNestedBlendsAreRefused) {
  const fs::path file = uniquePath("blends") += ".json";
  std::ofstream(file) << nestedBlends(10000);
  expectBadInput({"check", file.string()}, {file.string(), "nested more than 64 levels deep"});
  fs::remove(file);
}

TEST(HostileJson, NestedBlendsWithinTheJsonLimitMeetTheBlendLimit) {
  expectBadInput({"check", nestedBlends(20)}, {"materials", "nests materials too deeply"});
}

TEST(HostileJson, DeepModelSpecOfFitIsRefused) {
  expectBadInput({"fit", R"({"type":"lambertian"})", "--model", nestedArrays(5000), "--metric", "l2"},
                 {"--model", "nested more than 64 levels deep"});
}

TEST(HostileJson, NumberThatOverflowsNamesItsKey) {
  expectBadInput({"check", R"({"type":"conductor","alpha":1e999})"},
                 {"\"alpha\"", "1e999", "too large for a double"});
  expectBadInput({"render", R"({"type":"lambertian","albedo":[0.5,-1e400,0.5]})", "--out", "x"},
                 {"\"albedo\"", "-1e400"});
}

TEST(HostileJson, BracketsInsideStringsDoNotCount) {
  // 200 '[' inside a string are text, not nesting: the material is refused for its key only.
  expectBadInput({"check", R"({"type":"lambertian","note":")" + std::string(200, '[') + R"("})"},
                 {"\"note\"", "is not a key of model"});
}

}  // namespace hostile_json_cli_test
}  // namespace scatterlab
