#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "materials/core/temporary_files.h"

namespace scatterlab {
namespace temporary_files_test {

namespace fs = std::filesystem;

// An empty directory for one test, under the test binary's output directory.
fs::path freshDirectory(const std::string& name) {
  const fs::path directory = fs::path(SCATTERLAB_TEST_OUTPUT_DIR) / "temporary_files" / name;
  fs::remove_all(directory);
  fs::create_directories(directory);
  return directory;
}

std::vector<std::string> entriesOf(const fs::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory))
    names.push_back(entry.path().filename().string());
  return names;
}

TEST(TemporaryFiles, ATemporaryDirectoryIsCreatedEmptyAndRemovedByAnInterruption) {
  const fs::path parent = freshDirectory("created");
  const fs::path staging = parent / ".out.partial-1";
  std::ofstream(staging) << "a file of an earlier run in the way";
  std::error_code error;
  TemporaryPath directory = createTemporaryDirectory(staging, error);
  ASSERT_FALSE(error) << error.message();
  EXPECT_TRUE(fs::is_directory(staging));
  EXPECT_TRUE(fs::is_empty(staging));
  removeRegisteredTemporaries();
  EXPECT_EQ(entriesOf(parent), std::vector<std::string>{});
}

TEST(TemporaryFiles, ATemporaryDirectoryThatCannotBeCreatedSaysWhy) {
  const fs::path parent = freshDirectory("cannot");
  std::error_code error;
  const TemporaryPath directory = createTemporaryDirectory(parent / "missing" / ".out.partial-1", error);
  EXPECT_EQ(error, std::errc::no_such_file_or_directory) << error.message();
}

// The handler ends the process while it holds the lock, so a directory created under the lock
// is created before the temporaries are removed or never. A wrong implementation could pass by
// chance (if the thread starts late), but a right one cannot fail.
TEST(TemporaryFiles, CreatingADirectoryWaitsWhileInterruptionsAreDeferred) {
  const fs::path nested = freshDirectory("waits") / "a" / "b";
  std::unique_lock interruptions = deferInterruptions();
  std::thread creator([&] { createDirectoriesUninterrupted(nested); });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_FALSE(fs::exists(nested));
  interruptions.unlock();
  creator.join();
  EXPECT_TRUE(fs::is_directory(nested));
}

// Another thread keeps creating files in a staging directory while the interruption removes
// it: the directory must be gone all the same, under its name and under any other.
TEST(TemporaryFiles, AStagingDirectoryIsRemovedWhileAnotherThreadFillsIt) {
  const fs::path parent = freshDirectory("filled");
  const fs::path staging = parent / ".out.partial-1";
  std::error_code error;
  TemporaryPath directory = createTemporaryDirectory(staging, error);
  ASSERT_FALSE(error) << error.message();
  std::atomic<bool> stop = false;
  std::atomic<int> written = 0;
  std::thread writer([&] {
    for (int i = 0; !stop; ++i)
      if (std::ofstream(staging / std::to_string(i))) ++written;
  });
  while (written < 100) std::this_thread::yield();
  removeRegisteredTemporaries();
  EXPECT_EQ(entriesOf(parent), std::vector<std::string>{});
  // The writer goes on trying; with the directory gone it cannot create a file.
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  stop = true;
  writer.join();
  EXPECT_EQ(entriesOf(parent), std::vector<std::string>{});
}

}  // namespace temporary_files_test
}  // namespace scatterlab
