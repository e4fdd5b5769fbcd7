#include "app/lab/staged_directory.h"

#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include <nlohmann/json.hpp>

#include "app/exit_code.h"

namespace scatterlab {

namespace fs = std::filesystem;

namespace {

std::string inQuotes(const fs::path& path) { return "\"" + path.string() + "\""; }

// A name beside `target` that no other process uses: .NAME.TAG-PID-N.
fs::path siblingName(const fs::path& target, const std::string& tag) {
  static int counter = 0;
  const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  for (;; ++counter) {
    const fs::path candidate = parent / ("." + target.filename().string() + "." + tag + "-" +
                                         std::to_string(getpid()) + "-" + std::to_string(counter));
    std::error_code error;
    if (!fs::exists(fs::symlink_status(candidate, error))) return candidate;
  }
}

bool isEmptyDirectory(const fs::path& directory) {
  std::error_code error;
  return fs::is_empty(directory, error) && !error;
}

}  // namespace

bool isGeneratedDirectory(const fs::path& directory, const std::string& markerFile,
                          const std::string& generator) {
  std::ifstream in(directory / markerFile);
  if (!in) return false;
  const nlohmann::json marker = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  return marker.is_object() && marker.value("generator", std::string()) == generator;
}

StagedDirectory::StagedDirectory(fs::path target, std::string markerFile, std::string generator,
                                 std::string optionName)
    : target_(std::move(target)) {
  const std::string allowed =
      "; allowed: a new path, an empty directory, or a report this command wrote before";
  if (target_.empty()) throw InputError(optionName + ": an empty path" + allowed);
  target_ = fs::absolute(target_).lexically_normal();
  if (target_.filename().empty()) target_ = target_.parent_path();  // "dir/" names "dir"
  std::error_code error;
  const fs::file_status status = fs::symlink_status(target_, error);
  if (fs::exists(status)) {
    if (!fs::is_directory(status))
      throw InputError(optionName + ": " + inQuotes(target_) + " exists and is not a directory" + allowed);
    if (!isEmptyDirectory(target_) && !isGeneratedDirectory(target_, markerFile, generator))
      throw InputError(optionName + ": " + inQuotes(target_) + " is a directory with other files in it (no " +
                       markerFile + " from " + generator + "), which would be replaced" + allowed);
  }
  const fs::path parent = target_.parent_path();
  if (!parent.empty()) {
    fs::create_directories(parent, error);
    if (error || !fs::is_directory(parent))
      throw InputError(optionName + ": cannot create the directory " + inQuotes(parent) + " (" +
                       (error ? error.message() : "a file is in the way") + ")" + allowed);
  }
  staging_ = siblingName(target_, "partial");
  if (!fs::create_directory(staging_, error) || error)
    throw InputError(optionName + ": cannot create " + inQuotes(staging_) + " beside " + inQuotes(target_) +
                     " (" + (error ? error.message() : "it exists") +
                     "); allowed: a path in a writable directory");
}

StagedDirectory::~StagedDirectory() {
  std::error_code error;
  if (!committed_) fs::remove_all(staging_, error);
}

void StagedDirectory::commit() {
  std::error_code error;
  if (!fs::exists(fs::symlink_status(target_, error))) {
    fs::rename(staging_, target_);
    committed_ = true;
    return;
  }
  // Both exist: exchange them in one step, then remove the old one (now at the staging name).
  if (renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) == 0) {
    committed_ = true;
    fs::remove_all(staging_, error);
    return;
  }
  if (errno != EINVAL && errno != ENOSYS)
    throw std::runtime_error("cannot move " + inQuotes(staging_) + " to " + inQuotes(target_) + ": " +
                             std::strerror(errno));
  // The file system cannot exchange: the old directory aside, the new one in, the old one away.
  const fs::path old = siblingName(target_, "old");
  fs::rename(target_, old);
  try {
    fs::rename(staging_, target_);
  } catch (...) {
    fs::rename(old, target_, error);
    throw;
  }
  committed_ = true;
  fs::remove_all(old, error);
}

}  // namespace scatterlab
