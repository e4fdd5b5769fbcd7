// The report's output directory is replaced whole or not at all (app/lab/staged_directory.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "app/exit_code.h"
#include "app/lab/staged_directory.h"
#include "cli_runner.h"

namespace scatterlab {
namespace {

namespace fs = std::filesystem;
using cli_runner::readFile;
using cli_runner::uniquePath;

constexpr const char* Marker = "report.json";
constexpr const char* Generator = "scatterlab lab";

void writeFile(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

// A directory beside `target` whose name starts with ".TARGET." (a staging or old copy).
size_t leftovers(const fs::path& target) {
  size_t count = 0;
  for (const auto& entry : fs::directory_iterator(target.parent_path()))
    count += entry.path().filename().string().rfind("." + target.filename().string() + ".", 0) == 0 ? 1 : 0;
  return count;
}

TEST(StagedDirectory, CommitCreatesANewTarget) {
  const fs::path target = uniquePath("staged-new") / "report";
  {
    StagedDirectory staged(target, Marker, Generator, "--out");
    EXPECT_FALSE(fs::exists(target));  // nothing at the target until the commit
    writeFile(staged.path() / "index.html", "new");
    staged.commit();
  }
  EXPECT_EQ(readFile(target / "index.html"), "new");
  EXPECT_EQ(leftovers(target), 0u);
}

TEST(StagedDirectory, ReplacesAPreviousReportWhole) {
  const fs::path target = uniquePath("staged-replace") / "report";
  writeFile(target / Marker, R"({"generator": "scatterlab lab"})");
  writeFile(target / "old-only.png", "old");
  writeFile(target / "index.html", "old");
  {
    StagedDirectory staged(target, Marker, Generator, "--out");
    writeFile(staged.path() / "index.html", "new");
    EXPECT_EQ(readFile(target / "index.html"), "old");  // the old report stays until the commit
    staged.commit();
  }
  EXPECT_EQ(readFile(target / "index.html"), "new");
  EXPECT_FALSE(fs::exists(target / "old-only.png"));  // nothing of the old report is mixed in
  EXPECT_EQ(leftovers(target), 0u);
}

TEST(StagedDirectory, WithoutACommitTheTargetIsUntouched) {
  const fs::path target = uniquePath("staged-abort") / "report";
  writeFile(target / Marker, R"({"generator": "scatterlab lab"})");
  writeFile(target / "index.html", "old");
  try {
    StagedDirectory staged(target, Marker, Generator, "--out");
    writeFile(staged.path() / "index.html", "half");
    throw std::runtime_error("the report failed half-way");
  } catch (const std::runtime_error&) {}
  EXPECT_EQ(readFile(target / "index.html"), "old");
  EXPECT_EQ(leftovers(target), 0u);  // the staging directory is removed
}

TEST(StagedDirectory, AnEmptyDirectoryMayBeReplaced) {
  const fs::path target = uniquePath("staged-empty") / "report";
  fs::create_directories(target);
  StagedDirectory staged(target, Marker, Generator, "--out");
  writeFile(staged.path() / "index.html", "new");
  staged.commit();
  EXPECT_EQ(readFile(target / "index.html"), "new");
}

TEST(StagedDirectory, RefusesAFile) {
  const fs::path target = uniquePath("staged-file");
  writeFile(target, "someone's file");
  try {
    StagedDirectory staged(target, Marker, Generator, "--out");
    FAIL() << "a file was accepted as the output directory";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("is not a directory"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("--out"), std::string::npos) << error.what();
  }
  EXPECT_EQ(readFile(target), "someone's file");
}

TEST(StagedDirectory, RefusesADirectoryOfOtherFiles) {
  const fs::path target = uniquePath("staged-foreign") / "photos";
  writeFile(target / "holiday.png", "precious");
  writeFile(target / Marker, R"({"generator": "something else"})");
  EXPECT_THROW(StagedDirectory(target, Marker, Generator, "--out"), InputError);
  EXPECT_EQ(readFile(target / "holiday.png"), "precious");
  EXPECT_EQ(leftovers(target), 0u);
}

TEST(StagedDirectory, RecognisesItsOwnMarker) {
  const fs::path dir = uniquePath("staged-marker");
  EXPECT_FALSE(isGeneratedDirectory(dir, Marker, Generator));
  writeFile(dir / Marker, "not json");
  EXPECT_FALSE(isGeneratedDirectory(dir, Marker, Generator));
  writeFile(dir / Marker, R"({"generator": "scatterlab lab", "materials": []})");
  EXPECT_TRUE(isGeneratedDirectory(dir, Marker, Generator));
}

}  // namespace
}  // namespace scatterlab
