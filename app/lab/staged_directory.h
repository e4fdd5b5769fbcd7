// An output directory that is replaced whole or not at all (the lab report's DIR): everything
// is written into a fresh temporary directory beside the target, and commit() swaps it in
// with renames, so a reader (or a crash, or a failed run) sees the old directory or the new
// one, never a half-written mix.
//
// commit(): when the target exists, the two directories are exchanged atomically
// (renameat2 with RENAME_EXCHANGE, Linux 3.15+), and the old one, now at the temporary name,
// is removed; where the file system cannot exchange, the old directory is first renamed
// aside (the target is then briefly absent, never partial). Without a commit the destructor
// removes the temporary directory, leaving the target as it was.
//
// An existing target is replaced only when it is empty or was written by the same tool (it
// holds a marker file whose JSON names `generator`): a mistyped --out must not wipe a
// directory of someone's files.
#pragma once

#include <filesystem>
#include <string>

namespace scatterlab {

class StagedDirectory {
 public:
  // Checks `target` and creates the temporary directory (and `target`'s missing parents).
  // Throws InputError naming `optionName` and the path when `target` is a file, a non-empty
  // directory without the marker, or when the directory cannot be created.
  StagedDirectory(std::filesystem::path target, std::string markerFile, std::string generator,
                  std::string optionName);
  ~StagedDirectory();
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  // Where to write: the temporary directory until commit().
  const std::filesystem::path& path() const { return staging_; }
  const std::filesystem::path& target() const { return target_; }

  // Moves the staged directory to the target (see above). Throws std::runtime_error when a
  // rename fails; the target is then left as it was.
  void commit();

 private:
  std::filesystem::path target_, staging_;
  bool committed_ = false;
};

// True when `directory` holds `markerFile` whose JSON object has "generator": generator.
bool isGeneratedDirectory(const std::filesystem::path& directory, const std::string& markerFile,
                          const std::string& generator);

}  // namespace scatterlab
