// Temporary files and directories that must not outlive the process, not even when it is
// interrupted (docs/reliability.md, "Interruption"). Every temporary the tool creates beside an
// output (NAME.tmp-PID, .NAME.partial-PID-N) is registered here while it exists; the command
// line's signal handling (app/interrupt_cleanup.h) removes every registered one before the
// process ends.
//
// A commit (renaming staged outputs over the old ones) holds deferInterruptions(): a signal
// that arrives meanwhile waits until every output is in place, so an interruption leaves the
// old set or the new set, never a mix.
//
// A process killed by SIGKILL cannot clean up; its temporaries carry its PID, and the next
// run removes those whose process no longer exists (removeStaleTemporaries).
#pragma once

#include <filesystem>
#include <mutex>
#include <string>

namespace scatterlab {

// A registered temporary: removed (with its contents, for a directory) when the process is
// interrupted, and by the destructor unless keep() was called (after it was renamed into
// place). Thread-safe.
class TemporaryPath {
 public:
  TemporaryPath() = default;
  explicit TemporaryPath(std::filesystem::path path);
  ~TemporaryPath();
  TemporaryPath(TemporaryPath&& other) noexcept;
  TemporaryPath& operator=(TemporaryPath&& other) noexcept;
  TemporaryPath(const TemporaryPath&) = delete;
  TemporaryPath& operator=(const TemporaryPath&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // The path now holds a finished output (renamed into place): unregister, do not remove.
  void keep();
  // Removes the path now and unregisters it.
  void remove();

 private:
  std::filesystem::path path_;
};

// Held while outputs are renamed into place; a signal is handled once it is released.
std::unique_lock<std::recursive_mutex> deferInterruptions();

// Removes every registered temporary (under the lock of deferInterruptions). For the
// interruption handler, which then ends the process.
void removeRegisteredTemporaries();

// std::filesystem::create_directories under the lock of deferInterruptions. Other threads go
// on working while the interruption handler removes the temporaries; a plain
// create_directories of a directory inside a staging directory would re-create the staging
// directory (it creates missing parents) just after the handler removed it. Under the lock it
// runs before the removal or not at all (the handler ends the process holding the lock).
bool createDirectoriesUninterrupted(const std::filesystem::path& directory, std::error_code& error);
void createDirectoriesUninterrupted(const std::filesystem::path& directory);

// Registers `path` and creates it as an empty directory (removing whatever was there), both
// under the lock of deferInterruptions, so an interruption finds it registered whenever it
// exists. `error` says why the directory could not be created; the path stays registered.
TemporaryPath createTemporaryDirectory(const std::filesystem::path& path, std::error_code& error);

// The suffix this process gives temporaries: ".tmp-PID".
std::string temporarySuffix();

// Removes the leftovers of dead processes beside `target`: entries of its directory named
// NAME.tmp-PID, .NAME.partial-PID (either followed by nothing, or by '.' or '-' and more) whose
// PID is no running process. Entries of running processes (another run writing the same output) are left
// alone. Returns how many were removed; never throws.
int removeStaleTemporaries(const std::filesystem::path& target);

}  // namespace scatterlab
