// Bounded memory and time: every reader checks a size before it reads (a device, a huge file),
// a gallery counts against the pixel limit, and work that would take more than a minute is
// announced with an estimate before it starts; progress goes to stderr also when it is not a
// terminal, and --quiet silences it.
#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "cli_runner.h"

namespace scatterlab {
namespace resources_cli_test {

using namespace cli_runner;

const std::string Lambertian = R"({"type":"lambertian","albedo":0.5})";

// Runs `args` in the background until stderr mentions `fragment` (or `seconds` pass), then
// interrupts it; returns the run.
ProcessResult runUntilStderrMentions(const std::vector<std::string>& args, const std::string& fragment,
                                     double seconds) {
  const RunningProcess process = startScatterlab(args);
  waitUntil([&] { return readFile(process.errPath).find(fragment) != std::string::npos; }, seconds);
  kill(process.pid, SIGINT);
  return finishScatterlab(process);
}

TEST(BoundedInput, DevicesAreNotReadWhole) {
  for (const char* device : {"/dev/zero", "/dev/urandom"}) {
    SCOPED_TRACE(device);
    const auto start = std::chrono::steady_clock::now();
    expectBadInput({"check", device}, {device, "holds more than the 4 MB allowed"});
    expectBadInput({"fit", device, "--model", "lambertian", "--metric", "l2"}, {device});
    expectBadInput({"synth", "--fit", device, "--name", "x", "--out", uniquePath("t").string()}, {device});
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
  }
}

TEST(BoundedInput, AHugeFileIsRefusedBeforeItIsRead) {
  const fs::path file = uniquePath("huge") += ".json";
  { std::ofstream(file) << "{"; }
  fs::resize_file(file, uintmax_t(8) << 30);  // sparse: 8 GB that take no disk
  expectBadInput({"check", file.string()}, {file.string(), "is 8192 MB, more than the 4 MB allowed"});
  const fs::path table = uniquePath("huge") += ".binary";
  { std::ofstream(table) << "x"; }
  fs::resize_file(table, uintmax_t(8) << 30);
  // Its first bytes are no MERL or RGL header, so it is read as a material file: refused by size,
  // before it is read, like the JSON file above.
  expectBadInput({"fit", table.string(), "--model", "lambertian", "--metric", "l2"},
                 {table.string(), "is 8192 MB, more than the 4 MB allowed"});
  fs::remove(file);
  fs::remove(table);
}

TEST(BoundedWork, AGalleryCountsAgainstThePixelLimit) {
  expectBadInput({"render", Lambertian, Lambertian, Lambertian, Lambertian, "--res", "4096", "--out", "x"},
                 {"--res", "4 materials x 4096x4096", "at most 33554432 pixels in all"});
}

TEST(BoundedWork, HoursOfWorkAreAnnouncedFirst) {
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"check", R"({"type":"lambertian"})", "--samples", "1e11"},
           {"check", R"({"type":"lambertian"})", "--grid", "4096x4096", "--samples", "1e8"},
           {"render", Lambertian, "--res", "64", "--spp", "1048576", "--out", uniquePath("long").string()},
           {"profile", R"({"type":"subsurface"})", "--reference", "walk", "--albedo", "1", "--paths", "1e10"},
           {"shape-factor", "--albedos", "0.999", "--paths", "1e10"}}) {
    SCOPED_TRACE(args.front());
    const ProcessResult run = runUntilStderrMentions(args, "of memory", 60.0);
    EXPECT_EQ(run.exitCode, 128 + SIGINT) << describe(run);
    expectMentions(run.err, {"scatterlab: " + args.front(), "about", "of memory", "Ctrl-C"});
  }
}

TEST(BoundedWork, ProgressLinesReachALogAndQuietSilencesThem) {
  // A row of a 16-pixel tile is 1.6 M samples, about a second: lines come every 5 s.
  const std::vector<std::string> render{"render", Lambertian, "--res", "64",
                                        "--spp",  "100000",   "--out", uniquePath("progress").string()};
  ProcessResult run = runUntilStderrMentions(render, "left)", 30.0);
  expectMentions(run.err, {"render lambertian", "% (", "so far", "left)"});
  const RunningProcess quiet = startScatterlab(render + std::vector<std::string>{"--quiet"});
  sleep(7);  // longer than a progress interval
  kill(quiet.pid, SIGINT);
  run = finishScatterlab(quiet);
  EXPECT_EQ(run.exitCode, 128 + SIGINT);
  EXPECT_TRUE(run.err.empty()) << run.err;
}

}  // namespace resources_cli_test
}  // namespace scatterlab
