// An output directory that is replaced whole or not at all (the lab report's DIR): everything
// is written into a fresh temporary directory beside the target (.NAME.partial-PID-N), and
// commit() swaps it in with renames, so a reader (or a crash, or a failed or interrupted run)
// sees the old directory or the new one, never a half-written mix.
//
// commit(): the staged directory gets a manifest (manifest.json: the generator and every file
// and folder in it); when the target exists, the two directories are exchanged atomically
// (renameat2 with RENAME_EXCHANGE, Linux 3.15+), and the old one, now at the temporary name,
// is removed; where the file system cannot exchange, the old directory is first renamed aside
// (the target is then briefly absent, never partial). Without a commit the destructor removes
// the temporary directory, leaving the target as it was; an interruption (SIGINT, SIGTERM)
// removes it too (materials/core/temporary_files.h), and a commit in progress completes first.
//
// An existing target is replaced only when it is empty or provably this generator's: its
// manifest names the generator and lists everything in it. A mistyped --out must not wipe a
// directory of someone's files, nor a report into which someone put files of their own.
//
// While the object lives it holds a lock (.NAME.lock beside the target, flock): a second run
// with the same target is refused instead of silently discarding the first one's work.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/output_guard.h"
#include "materials/core/temporary_files.h"

namespace scatterlab {

inline constexpr const char* DirectoryManifestFile = "manifest.json";

class StagedDirectory {
 public:
  // Locks and checks `target`, and creates the temporary directory (and `target`'s missing
  // parents). Throws InputError naming `optionName` and the path when `target` is a file, a
  // directory this generator cannot prove its own, the directory of one of `inputs`, locked by
  // another run, or when the directory cannot be created.
  StagedDirectory(std::filesystem::path target, std::string generator, std::string optionName,
                  const std::vector<InputPath>& inputs = {});
  ~StagedDirectory();
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  // Where to write: the temporary directory until commit().
  const std::filesystem::path& path() const { return staging_.path(); }
  const std::filesystem::path& target() const { return target_; }

  // Moves the staged directory to the target (see above). Throws std::runtime_error when a
  // rename fails; the target is then left as it was.
  void commit();

 private:
  // Released (and its file removed) by the destructor, also when the constructor throws.
  struct Lock {
    int fd = -1;
    TemporaryPath file;  // an interruption removes it too
    ~Lock();
  };

  std::filesystem::path target_;
  std::string generator_;
  Lock lock_;
  TemporaryPath staging_;
};

// Why `directory` is not provably `generator`'s output: the first entry its manifest does not
// list, or a missing or foreign manifest; nothing when it is (or is empty).
std::optional<std::string> foreignContent(const std::filesystem::path& directory,
                                          const std::string& generator);

}  // namespace scatterlab
