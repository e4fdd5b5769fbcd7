// The report's output directory is replaced whole or not at all (app/lab/staged_directory.h).
#include <gtest/gtest.h>

#include <signal.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "app/exit_code.h"
#include "app/lab/staged_directory.h"
#include "cli_runner.h"

namespace scatterlab {
namespace lab_staged_directory_test {

namespace fs = std::filesystem;
using cli_runner::readFile;
using cli_runner::uniquePath;

constexpr const char* Generator = "scatterlab lab";

// The manifest an earlier run would have written for these files.
void writeManifest(const fs::path& dir, const std::vector<std::string>& files,
                   const std::vector<std::string>& directories = {}) {
  nlohmann::json manifest{{"generator", Generator}, {"files", files}, {"directories", directories}};
  std::ofstream(dir / "manifest.json") << manifest.dump();
}

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
    StagedDirectory staged(target, Generator, "--out");
    EXPECT_FALSE(fs::exists(target));  // nothing at the target until the commit
    writeFile(staged.path() / "index.html", "new");
    staged.commit();
  }
  EXPECT_EQ(readFile(target / "index.html"), "new");
  EXPECT_EQ(leftovers(target), 0u);
}

TEST(StagedDirectory, ReplacesAPreviousReportWhole) {
  const fs::path target = uniquePath("staged-replace") / "report";
  writeFile(target / "old-only.png", "old");
  writeFile(target / "index.html", "old");
  writeManifest(target, {"old-only.png", "index.html"});
  {
    StagedDirectory staged(target, Generator, "--out");
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
  writeFile(target / "index.html", "old");
  writeManifest(target, {"index.html"});
  try {
    StagedDirectory staged(target, Generator, "--out");
    writeFile(staged.path() / "index.html", "half");
    throw std::runtime_error("the report failed half-way");
  } catch (const std::runtime_error&) {}
  EXPECT_EQ(readFile(target / "index.html"), "old");
  EXPECT_EQ(leftovers(target), 0u);  // the staging directory is removed
}

TEST(StagedDirectory, AnEmptyDirectoryMayBeReplaced) {
  const fs::path target = uniquePath("staged-empty") / "report";
  fs::create_directories(target);
  StagedDirectory staged(target, Generator, "--out");
  writeFile(staged.path() / "index.html", "new");
  staged.commit();
  EXPECT_EQ(readFile(target / "index.html"), "new");
}

TEST(StagedDirectory, RefusesAFile) {
  const fs::path target = uniquePath("staged-file");
  writeFile(target, "someone's file");
  try {
    StagedDirectory staged(target, Generator, "--out");
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
  writeFile(target / "report.json", R"({"generator": "scatterlab lab"})");
  EXPECT_THROW(StagedDirectory(target, Generator, "--out"), InputError);
  EXPECT_EQ(readFile(target / "holiday.png"), "precious");
  EXPECT_EQ(leftovers(target), 0u);
}

TEST(StagedDirectory, ProvesADirectoryItsOwnByTheManifestAlone) {
  const fs::path dir = uniquePath("staged-manifest");
  fs::create_directories(dir);
  EXPECT_FALSE(foreignContent(dir, Generator));  // empty
  writeFile(dir / "index.html", "page");
  writeFile(dir / "gold" / "data.json", "{}");
  EXPECT_TRUE(foreignContent(dir, Generator));  // no manifest
  writeFile(dir / "manifest.json", "not json");
  EXPECT_TRUE(foreignContent(dir, Generator));
  writeManifest(dir, {"index.html", "gold/data.json"}, {"gold"});
  EXPECT_FALSE(foreignContent(dir, Generator));
  writeFile(dir / "gold" / "notes.txt", "mine");
  const auto foreign = foreignContent(dir, Generator);
  ASSERT_TRUE(foreign);
  EXPECT_NE(foreign->find("gold/notes.txt"), std::string::npos) << *foreign;
  fs::remove(dir / "gold" / "notes.txt");
  fs::create_symlink("/etc", dir / "gold" / "link");
  EXPECT_TRUE(foreignContent(dir, Generator));  // a link is nothing it writes
}

TEST(StagedDirectory, TheCommitListsEveryFileInTheManifest) {
  const fs::path target = uniquePath("staged-lists") / "report";
  {
    StagedDirectory staged(target, Generator, "--out");
    writeFile(staged.path() / "index.html", "new");
    writeFile(staged.path() / "gold" / "data.json", "{}");
    staged.commit();
  }
  EXPECT_FALSE(foreignContent(target, Generator));
}

TEST(StagedDirectory, ASecondWriterOfTheSameTargetIsRefused) {
  const fs::path target = uniquePath("staged-lock") / "report";
  StagedDirectory first(target, Generator, "--out");
  try {
    StagedDirectory second(target, Generator, "--out");
    FAIL() << "two writers of one directory";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("is being written by another run"), std::string::npos)
        << error.what();
  }
}

TEST(StagedDirectory, LeftoversOfDeadRunsAreRemoved) {
  const fs::path target = uniquePath("staged-stale") / "report";
  pid_t dead = 4000000;
  while (dead > 1000 && !(kill(dead, 0) == -1 && errno == ESRCH)) --dead;
  const fs::path stale = target.parent_path() / (".report.partial-" + std::to_string(dead) + "-0");
  writeFile(stale / "index.html", "half a report");
  { StagedDirectory staged(target, Generator, "--out"); }
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_EQ(leftovers(target), 0u);
}

TEST(StagedDirectory, RefusesADirectoryHoldingAnInput) {
  const fs::path target = uniquePath("staged-input") / "report";
  writeFile(target / "gold.json", "{}");
  EXPECT_THROW(StagedDirectory(target, Generator, "--out", {{"material file", target / "gold.json"}}),
               InputError);
  EXPECT_EQ(readFile(target / "gold.json"), "{}");
}

}  // namespace lab_staged_directory_test
}  // namespace scatterlab
