#include "app/lab/staged_directory.h"

#include <fcntl.h>
#include <stdio.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <set>
#include <stdexcept>
#include <system_error>

#include <nlohmann/json.hpp>

#include "app/exit_code.h"
#include "app/staged_outputs.h"
#include "materials/core/atomic_file.h"
#include "materials/core/bounded_file.h"
#include "materials/core/json_text.h"
#include "materials/core/quoted.h"
#include "materials/core/temporary_files.h"

namespace scatterlab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A name beside `target` that no other process uses: .NAME.TAG-PID-N.
fs::path siblingName(const fs::path& target, const std::string& tag) {
  static int counter = 0;
  for (;; ++counter) {
    const fs::path candidate =
        target.parent_path() / ("." + target.filename().string() + "." + tag + "-" +
                                std::to_string(getpid()) + "-" + std::to_string(counter));
    std::error_code error;
    if (!fs::exists(fs::symlink_status(candidate, error))) return candidate;
  }
}

// Every file and folder below `directory`, relative to it, sorted.
struct Listing {
  std::set<std::string> files, directories, other;
};
Listing listDirectory(const fs::path& directory) {
  Listing listing;
  std::error_code error;
  for (fs::recursive_directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
    const std::string relative = it->path().lexically_relative(directory).generic_string();
    const fs::file_status status = it->symlink_status(error);
    if (fs::is_directory(status))
      listing.directories.insert(relative);
    else if (fs::is_regular_file(status))
      listing.files.insert(relative);
    else
      listing.other.insert(relative);
  }
  if (error) listing.other.insert("(unreadable: " + error.message() + ")");
  return listing;
}

std::set<std::string> stringSet(const json& value) {
  std::set<std::string> out;
  if (!value.is_array()) return out;
  for (const json& entry : value)
    if (entry.is_string()) out.insert(entry.get<std::string>());
  return out;
}

// The size limit of the manifest a directory of a few thousand files needs.
constexpr uintmax_t MaxManifestBytes = uintmax_t(16) << 20;

}  // namespace

std::optional<std::string> foreignContent(const fs::path& directory, const std::string& generator) {
  std::error_code error;
  if (fs::is_empty(directory, error) && !error) return std::nullopt;
  json manifest;
  try {
    manifest = parseJsonText(readFileBounded(directory / DirectoryManifestFile, MaxManifestBytes, "manifest"),
                             DirectoryManifestFile);
  } catch (const std::exception&) {
    return std::string("it has no readable ") + DirectoryManifestFile + " from " + generator;
  }
  if (!manifest.is_object() || manifest.value("generator", std::string()) != generator)
    return std::string("its ") + DirectoryManifestFile + " is not from " + generator;
  const std::set<std::string> files = stringSet(manifest.value("files", json())),
                              directories = stringSet(manifest.value("directories", json()));
  const Listing listing = listDirectory(directory);
  if (!listing.other.empty())
    return "it holds " + inQuotes(*listing.other.begin()) + ", not a file or folder";
  for (const std::string& file : listing.files)
    if (file != DirectoryManifestFile && !files.count(file))
      return "it holds " + inQuotes(file) + ", which " + generator + " did not write (not in its " +
             DirectoryManifestFile + ")";
  for (const std::string& folder : listing.directories)
    if (!directories.count(folder))
      return "it holds the folder " + inQuotes(folder) + ", which " + generator + " did not write";
  return std::nullopt;
}

StagedDirectory::StagedDirectory(fs::path target, std::string generator, std::string optionName,
                                 const std::vector<InputPath>& inputs)
    : target_(std::move(target)), generator_(std::move(generator)) {
  const std::string allowed = "; allowed: a new path, an empty directory, or a report " + generator_ +
                              " wrote before (nothing else in it)";
  if (target_.empty()) throw InputError(optionName + ": an empty path" + allowed);
  target_ = fs::absolute(target_).lexically_normal();
  if (target_.filename().empty()) target_ = target_.parent_path();  // "dir/" names "dir"
  std::error_code error;
  const fs::file_status status = fs::symlink_status(target_, error);
  if (fs::exists(status) && !fs::is_directory(status))
    throw InputError(optionName + ": " + inQuotes(target_.string()) + " exists and is not a directory" +
                     allowed);
  refuseOutputOverInputs(optionName, target_, OutputKind::ReplacedDirectory, inputs);

  const fs::path parent = target_.parent_path();
  createOutputDirectory(optionName, parent, allowed);

  // One run per target: the lock is released when this process ends, however it ends.
  const fs::path lockPath = parent / ("." + target_.filename().string() + ".lock");
  // Created and registered under one lock, so an interruption finds it registered.
  std::unique_lock interruptions = deferInterruptions();
  for (;;) {
    lock_.fd = ::open(lockPath.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (lock_.fd < 0)
      throw InputError(optionName + ": cannot create " + inQuotes(lockPath.string()) + " (" +
                       std::strerror(errno) + "); allowed: a path in a writable directory");
    if (::flock(lock_.fd, LOCK_EX | LOCK_NB) != 0) {
      char owner[32] = {};
      if (::pread(lock_.fd, owner, sizeof owner - 1, 0) < 0) owner[0] = '?';
      ::close(lock_.fd);
      lock_.fd = -1;
      throw InputError(optionName + ": " + inQuotes(target_.string()) +
                       " is being written by another run (process " + std::string(owner) +
                       "); allowed: wait for it to finish, or another directory");
    }
    // The previous holder may have removed the file between our open and our lock: then the
    // lock is on a file nobody else sees; try again on the file that is there now.
    struct stat held {
    }, current{};
    if (::fstat(lock_.fd, &held) == 0 && ::stat(lockPath.c_str(), &current) == 0 &&
        held.st_ino == current.st_ino && held.st_dev == current.st_dev)
      break;
    ::close(lock_.fd);
    lock_.fd = -1;
  }
  lock_.file = TemporaryPath(lockPath);
  interruptions.unlock();
  const std::string pid = std::to_string(getpid());
  if (::ftruncate(lock_.fd, 0) != 0 || ::pwrite(lock_.fd, pid.data(), pid.size(), 0) < 0) {
    // The PID only makes the other run's message more helpful.
  }

  if (fs::exists(status))
    if (const auto foreign = foreignContent(target_, generator_))
      throw InputError(optionName + ": " + inQuotes(target_.string()) +
                       " is a directory this command cannot " + "replace: " + *foreign + allowed);
  removeStaleTemporaries(target_);
  staging_ = createTemporaryDirectory(siblingName(target_, "partial"), error);
  if (error)
    throw InputError(optionName + ": cannot create " + inQuotes(staging_.path().string()) + " beside " +
                     inQuotes(target_.string()) + " (" + error.message() +
                     "); allowed: a path in a writable directory");
}

StagedDirectory::Lock::~Lock() {
  if (fd < 0) return;
  file.remove();  // while still holding it: the next run creates a fresh one
  ::close(fd);
}

StagedDirectory::~StagedDirectory() { staging_.remove(); }

void StagedDirectory::commit() {
  const Listing listing = listDirectory(staging_.path());
  const json manifest{
      {"generator", generator_},
      {"files", std::vector<std::string>(listing.files.begin(), listing.files.end())},
      {"directories", std::vector<std::string>(listing.directories.begin(), listing.directories.end())}};
  writeTextFileAtomically(staging_.path() / DirectoryManifestFile, manifest.dump(1) + "\n");

  const auto interruptions = deferInterruptions();
  std::error_code error;
  if (!fs::exists(fs::symlink_status(target_, error))) {
    fs::rename(staging_.path(), target_);
    staging_.keep();
    return;
  }
  // Both exist: exchange them in one step, then remove the old one (now at the staging name).
  if (renameat2(AT_FDCWD, staging_.path().c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) == 0) {
    staging_.remove();
    return;
  }
  if (errno != EINVAL && errno != ENOSYS)
    throw std::runtime_error("cannot move " + inQuotes(staging_.path().string()) + " to " +
                             inQuotes(target_.string()) + ": " + std::strerror(errno));
  // The file system cannot exchange: the old directory aside, the new one in, the old one away.
  TemporaryPath old(siblingName(target_, "partial"));
  fs::rename(target_, old.path());
  try {
    fs::rename(staging_.path(), target_);
  } catch (...) {
    fs::rename(old.path(), target_, error);
    old.keep();
    throw;
  }
  staging_.keep();
  old.remove();
}

}  // namespace scatterlab
